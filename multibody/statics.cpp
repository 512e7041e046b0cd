#include "multibody/statics.hpp"

#include "multibody/checks.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "modal/buckling.hpp"
#include "modal/gyroscopic.hpp"
#include "modal/modes.hpp"
#include "ring/errors.hpp"

#include "multibody/natural.hpp"
#include "multibody/plates.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/dynamics_sparse.hpp"
#include "multibody/linear_model.hpp"
#include "multibody/sections.hpp"
#include "multibody/static_equilibria.hpp"
#include "multibody/spin.hpp"

namespace multibody {
namespace detail {

StaticEquilibrium::StaticEquilibrium(const Chain& chain, const ring::RingSpec& spec, double depth)
    : chain_(chain), depth_(depth), gap_(contact_gap(chain, depth)), bending_(spec, chain) {}

ring::PathPoint StaticEquilibrium::path_point(double s, const Eigen::Matrix2Xd& p) const {
  ring::PathPoint pt;
  pt.load_factor = s;
  for (int k : record_) {
    const Eigen::Vector2d u = p.col(k) - chain_.hinge_rest(k);
    pt.displacements.push_back({chain_.hinge_angles_deg()[k], u.x(), u.y()});
  }
  const int n = chain_.n();
  if (!chain_.arch()) {  // the spread of the diameters: a closed ring's measure
    double most = 0.0, least = HUGE_VAL;
    for (int k = 0; k < (n + 1) / 2; ++k) {
      const double d = (p.col(k) - p.col((k + n / 2) % n)).norm();
      most = std::max(most, d);
      least = std::min(least, d);
    }
    pt.ovalisation = (most - least) / chain_.circumradius();
  }
  pt.dissipated = dissipated();
  pt.plastic_curvature = plastic_curvature();
  for (int k = 0; k < n; k += ring::path_shape_stride(n)) {
    pt.node_x.push_back(p(0, k));
    pt.node_y.push_back(p(1, k));
  }
  if (chain_.arch()) {  // the far end closes the drawn arch
    pt.node_x.push_back(p(0, n));
    pt.node_y.push_back(p(1, n));
  }
  return pt;
}

std::optional<double> StaticEquilibrium::clearance(const paths::State& x) {
  return closest_contact(hinges(x.z), chain_.l(), gap_, depth_, !chain_.arch()).distance - depth_;
}

std::optional<paths::Touch> StaticEquilibrium::accept(const paths::State& from, const paths::State& to) {
  const Eigen::Matrix2Xd p = hinges(to.z);
  if (recording_ && path_.empty()) path_.push_back(point(from));
  // The step converged: its trial plastic states become the committed ones (ring/plastic.hpp).
  bending_.commit(hinge_strains(to.z));
  if (recording_) path_.push_back(point(to));
  const ClosestPair cp = closest_contact(p, chain_.l(), gap_, depth_, !chain_.arch());
  if (cp.distance >= depth_) return std::nullopt;
  std::ostringstream m;
  m << describe_contact(cp) << " (section depth " << depth_ << " m); the chain model does not include contact";
  return paths::Touch{1.0, m.str()};
}

ring::RingSpec held_spec(const ring::RingSpec& spec, const ring::StaticOptions& statics) {
  ring::RingSpec held = spec;
  // Appended last, so its rows are the last of the further pins' in both formulations
  // (Attachments::pins, natural::Natural::pins), whatever holds hinge 0.
  if (statics.displacement) held.supports.pins.push_back(statics.displacement->at);
  return held;
}

}  // namespace detail
namespace detail {

DenseTangent::DenseTangent(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads,
                           const std::string& section, const HingeBending* bending)
    : chain_(chain),
      bending_(bending),
      loads_(chain, spec, loads, section),
      terms_(chain, spec),
      shear_(spec.theory == ring::Theory::timoshenko),
      K_(shear_ ? Sections(chain, &terms_, Shear::of(spec, chain.l())).condensed() : chain.stiffness_matrix()),
      n_(chain.dofs()),
      c_(chain.constraint_count() + terms_.pin_rows()) {}

Chain::ConstraintKinematics DenseTangent::constraints(const Vector& q) const { return terms_.constraints(q); }

Vector DenseTangent::internal_forces(const Vector& q) const {
  Vector forces = shear_     ? Vector(K_ * (q - chain_.q0()))
                  : bending_ ? bending_->forces_on_angles(chain_, q)
                             : chain_.spring_forces(q);
  terms_.add_stiffness(q, forces, nullptr, !shear_);  // Timoshenko: the rotations' terms are in K_c
  return forces;
}

void DenseTangent::add_terms(const Vector& q, Eigen::Ref<Matrix> T) const {
  Vector unused = Vector::Zero(n_);
  terms_.add_stiffness(q, unused, &T, !shear_);
}

void DenseTangent::add_tangent(const Vector& q, const Vector& lambda, double s, const Chain::ConstraintKinematics& ck,
                               Eigen::Ref<Matrix> T) const {
  if (bending_ && !shear_)
    bending_->add_tangent_on_angles(chain_, q, T);
  else
    T += K_;
  add_terms(q, T);
  loads_.add_stiffness(q, s, T);
  T.diagonal() += ck.hess.transpose() * lambda;
}

}  // namespace detail
namespace {

/// The dense path: unknowns z = (segment angles q, multipliers lambda). The bordered
/// tangent [T sc G^T -Phi; sc G 0 sc dg/ds; w^T 0 ws] (T: detail::DenseTangent), with the
/// constraint rows and the multipliers scaled by sc = K / l (G on the scale of the
/// springs), by dense LU: O(n^3). dg/ds is -v on the driven rows (the last two) under
/// static.displacement (statics.hpp), zero otherwise.
class AngleStatics : public detail::StaticEquilibrium {
 public:
  AngleStatics(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads, double depth,
               std::optional<Eigen::Vector2d> drive = std::nullopt,
               const ring::StaticOptions::Plates* plates = nullptr)
      : StaticEquilibrium(chain, spec, depth),
        tangent_(chain, spec, loads, "static", &bending_),
        n_(tangent_.dofs()),
        c_(tangent_.rows() + (plates ? 3 : 0)),
        sc_(chain.K() / chain.l()),
        drive_(drive) {
    if (drive_ && c_ < 2) throw std::logic_error("multibody: a driven point needs its two pin rows (held_spec)");
    if (plates) plates_.emplace(chain, spec, *plates);
  }
  Eigen::Index size() const override { return n_ + c_; }
  Eigen::Index arc_size() const override { return n_; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override {
    const Vector q = x.z.head(n_), lambda = x.z.tail(c_);
    const Chain::ConstraintKinematics ck = constraints(q);
    const Vector phi = tangent_.loads().forces(q);
    Vector forces = tangent_.internal_forces(q) + ck.G.transpose() * lambda - x.s * phi, rate = -phi;
    Matrix A = Matrix::Zero(n_ + c_ + 1, n_ + c_ + 1);
    Eigen::Ref<Matrix> T = A.topLeftCorner(n_, n_);
    tangent_.add_tangent(q, lambda, x.s, ck, T);
    if (plates_) plates_->add(q, x.s, forces, &T, rate);  // the plates' penalty and its rate in s
    r.resize(n_ + c_);
    r << forces, ck.g;
    if (drive_) r.tail<2>() -= x.s * *drive_;  // the driven pin's target s v
    if (!r.allFinite()) return false;
    A.block(0, n_, n_, c_) = sc_ * ck.G.transpose();
    A.block(n_, 0, c_, n_) = sc_ * ck.G;
    A.col(n_ + c_).head(n_) = rate;
    if (drive_) A.col(n_ + c_).segment<2>(n_ + c_ - 2) = -sc_ * *drive_;
    A.row(n_ + c_).head(n_) = w.transpose();
    A(n_ + c_, n_ + c_) = ws;
    lu_.compute(A);
    return true;  // a singular matrix shows as a non-finite solve
  }
  bool solve(paths::Vector& y) override {
    y.segment(n_, c_) *= sc_;
    y = lu_.solve(y).eval();
    y.segment(n_, c_) *= sc_;
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return dz.head(n_).cwiseAbs().maxCoeff() / detail::kBasin; }
  bool converged(const paths::State&, const paths::Vector& dz, int) override {
    return dz.head(n_).cwiseAbs().maxCoeff() <= 1e-12;
  }
  /// The tangent T at x (n x n) and the constraints there.
  Matrix tangent(const paths::State& x, Chain::ConstraintKinematics& ck) const {
    ck = constraints(x.z.head(n_));
    return tangent_at(x, ck);
  }
  /// The inertia of T on the constraints' tangent space at x: O(n^3), once per accepted step.
  std::optional<int> unstable_directions(const paths::State& x) override {
    const Chain::ConstraintKinematics ck = constraints(x.z.head(n_));
    return modal::unstable_directions(tangent_at(x, ck), ck.G);
  }
  /// Its least stable direction in the angles, multipliers zero: O(n^3).
  std::optional<paths::Vector> critical_direction(const paths::State& x) override {
    const Chain::ConstraintKinematics ck = constraints(x.z.head(n_));
    paths::Vector d = paths::Vector::Zero(n_ + c_);
    d.head(n_) = modal::least_stable(tangent_at(x, ck), ck.G).direction;
    return d;
  }
  Eigen::Matrix2Xd hinges(const paths::Vector& z) const override { return chain_.hinge_positions(z.head(n_)); }
  Eigen::VectorXd hinge_strains(const paths::Vector& z) const override {
    return chain_.hinge_rotations(z.head(n_));
  }
  paths::Vector rest() const override {
    paths::Vector z = paths::Vector::Zero(n_ + c_);
    z.head(n_) = chain_.q0();
    return z;
  }
  std::array<double, 2> reaction(const paths::Vector& z) const override {
    if (!drive_) return {0.0, 0.0};
    return {-z(n_ + c_ - 2), -z(n_ + c_ - 1)};
  }
  std::optional<PlateState> plates(const paths::State& x) const override {
    if (!plates_) return std::nullopt;
    const Eigen::Matrix2Xd p = hinges(x.z);
    return PlateState{plates_->reaction(p, x.s), plates_->contact_lengths(p, x.s), plates_->energy(p, x.s)};
  }

 private:
  /// The chain's rows, the further pins', then [plates]' two no-slide rows and centre row
  /// (plates.hpp).
  Chain::ConstraintKinematics constraints(const Vector& q) const {
    Chain::ConstraintKinematics ck = tangent_.constraints(q);
    if (!plates_) return ck;
    const Chain::ConstraintKinematics p = plates_->slide_rows(q);
    const Eigen::Index c = ck.g.size();
    const Eigen::Index m = p.g.size();
    ck.g.conservativeResize(c + m);
    ck.g.tail(m) = p.g;
    ck.G.conservativeResize(c + m, Eigen::NoChange);
    ck.G.bottomRows(m) = p.G;
    ck.hess.conservativeResize(c + m, Eigen::NoChange);
    ck.hess.bottomRows(m) = p.hess;
    return ck;
  }
  Matrix tangent_at(const paths::State& x, const Chain::ConstraintKinematics& ck) const {
    Matrix T = Matrix::Zero(n_, n_);
    tangent_.add_tangent(x.z.head(n_), x.z.tail(c_), x.s, ck, T);
    if (plates_) {
      Vector unused = Vector::Zero(n_), rate = Vector::Zero(n_);
      Eigen::Ref<Matrix> Tr(T);
      plates_->add(x.z.head(n_), x.s, unused, &Tr, rate);
    }
    return T;
  }

  const detail::DenseTangent tangent_;
  const Eigen::Index n_, c_;
  const double sc_;
  const std::optional<Eigen::Vector2d> drive_;  ///< static.displacement.value, m
  std::optional<detail::PlateContact> plates_;   ///< [plates]
  Eigen::PartialPivLU<Matrix> lu_;
};

}  // namespace

std::unique_ptr<detail::StaticEquilibrium> detail::angle_equilibrium(const Chain& chain, const ring::RingSpec& spec,
                                                                     const ring::Loads& loads, double depth,
                                                                     std::optional<Eigen::Vector2d> drive,
                                                                     const ring::StaticOptions::Plates* plates) {
  return std::make_unique<AngleStatics>(chain, spec, loads, depth, drive, plates);
}

namespace {

/// The modes' pencil about the equilibrium x of `eq` (the modes under load, the spinning
/// ring's): the tangent T and the mass M on every unknown, (q[, gamma][, chi]), and Z, the
/// constraints' tangent space at q for q and every extra unknown (they enter no constraint).
struct LoadedPencil {
  Vector q;     ///< the chain's coordinates at the equilibrium
  Matrix T, M;  ///< on every unknown
  Matrix Z;     ///< every unknown x the reduced problem's
};

LoadedPencil loaded_pencil(const Chain& ch, const ring::RingSpec& spec, const AngleStatics& eq, const paths::State& x) {
  LoadedPencil p;
  Chain::ConstraintKinematics ck;
  p.T = eq.tangent(x, ck);
  p.q = x.z.head(ch.dofs());
  p.Z = modal::kernel_basis(ck.G, ch.dofs());
  const detail::Attachments terms(ch, spec);
  p.M = detail::mass_matrix(ch, &terms, p.q);  // the chain's and the point masses' about q
  // The shear angles and the point inertias' hinge rotations back as unknowns (q, [gamma,]
  // chi). The shear angles (sections.hpp): T holds K_c = A - A (A + S)^{-1} A, the Schur
  // complement over gamma of [A, A; A, A + S], so on (phi, gamma) the full tangent is
  // [T - K_c + A, A; A, A + S] and the mass [M(q) + J, J; J, J]. The hinge rotations
  // (attachments.hpp): T holds what condensing chi gives, H's border restores chi with its
  // inertia J (on the sections' rotations on the Timoshenko chain).
  const bool shear = spec.theory == ring::Theory::timoshenko;
  std::optional<detail::HingeInertias> hinges;  // its (n + p)^2 border only where there is one
  if (detail::has_point_inertia(spec)) hinges.emplace(ch, terms, shear);
  if (!shear && !hinges) return p;
  const Eigen::Index d = ch.dofs(), N = d + (shear ? ch.n() : 0) + (hinges ? hinges->n() : 0), extra = N - d;
  Matrix Tf = Matrix::Zero(N, N), Mf = Matrix::Zero(N, N);
  Tf.topLeftCorner(d, d) = p.T;
  Mf.topLeftCorner(d, d) = p.M;
  if (shear) {
    const detail::Sections sections(ch, &terms, Shear::of(spec, ch.l()));
    sections.add_stiffness(Tf);
    Tf.topLeftCorner(d, d) -= sections.condensed();
    sections.add_mass(1.0, Mf);
  }
  if (hinges) {
    hinges->add_stiffness(1.0, Tf);
    hinges->add_mass(1.0, Mf);
  }
  Matrix Zf = Matrix::Zero(N, p.Z.cols() + extra);
  Zf.topLeftCorner(d, p.Z.cols()) = p.Z;
  Zf.bottomRightCorner(extra, extra).setIdentity();
  p.T = std::move(Tf);
  p.M = std::move(Mf);
  p.Z = std::move(Zf);
  return p;
}

}  // namespace

ring::ModalResult compute_modes_under_load(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                           const ring::StaticOptions& statics, int count) {
  check_preloaded_modes(spec, options, statics);
  const auto start = std::chrono::steady_clock::now();
  const std::optional<double> loaded =
      statics.loads.points.empty() ? std::nullopt : std::optional<double>(statics.loads.points.front().angle);
  const Chain ch(spec, options, loaded);
  AngleStatics eq(ch, spec, statics.loads, spec.section.depth());
  paths::Continuation policy;
  policy.steps = statics.steps;
  policy.history = statics.history;
  const paths::Trace path = paths::follow(eq, {eq.rest(), 0.0}, policy);
  if (path.end != paths::Trace::End::reached)
    throw ring::NumericalError("multibody modes under load: " + paths::failure_message(path, policy));
  // The pencil (Z^T T Z, Z^T M Z) at the equilibrium (modal::loaded_modes).
  const LoadedPencil p = loaded_pencil(ch, spec, eq, path.state);
  const Matrix Tr = p.Z.transpose() * p.T * p.Z, Mr = p.Z.transpose() * p.M * p.Z;
  const modal::LoadedModes m = modal::loaded_modes(Tr, Mr, modal::bending_scale(spec), count, "multibody modes under load");
  ring::ModalResult res;
  res.solver = "multibody";
  res.model["n"] = static_cast<long long>(ch.n());
  res.model["rotary_inertia"] = options.rotary_inertia;
  res.model["preload"] = std::string("static");
  res.unknowns = p.Z.cols();
  res.max_residual = m.max_residual;
  for (int k = 0; k < count; ++k) {
    res.omega.push_back(std::sqrt(m.omega2(k)));
    res.shapes.push_back(ch.shape_at(p.q, (p.Z * m.vectors.col(k)).head(ch.dofs())));
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

ring::ModalResult compute_spinning_modes(const ring::RingSpec& spec, const ring::MultibodyOptions& options, int count) {
  check_modes(spec, options);
  if (!spec.rotation.spinning())
    throw std::invalid_argument("multibody::compute_spinning_modes: rotation.speed is 0 (the modes at rest: compute_modes)");
  const auto start = std::chrono::steady_clock::now();
  const double speed = spec.rotation.speed;
  // The modes are elastic, as at rest: the spin's equilibrium on the elastic hinges.
  ring::RingSpec elastic = spec;
  elastic.plastic.reset();
  const Chain ch(elastic, options);
  // Loading adds the centrifugal body force of a spinning spec (loading.hpp): with no other
  // load, the statics' equilibrium at load factor 1 is the spin's, and the factor scales
  // speed^2 along the path.
  AngleStatics eq(ch, elastic, ring::Loads{}, elastic.section.depth());
  const bool tension = spec.rotation.tension == ring::Rotation::Tension::spin;
  paths::State state{eq.rest(), 0.0};
  if (tension) {
    paths::Continuation policy;
    policy.steps = 5;  // the spin's equilibrium is mild (the free ring's: the rest polygon itself)
    const paths::Trace path = paths::follow(eq, state, policy);
    if (path.end != paths::Trace::End::reached)
      throw ring::NumericalError("multibody spinning modes (the spin's equilibrium, rotation.tension = \"spin\"): " +
                                 paths::failure_message(path, policy));
    state = path.state;
  }
  LoadedPencil p = loaded_pencil(ch, elastic, eq, state);
  const detail::Attachments terms(ch, elastic);
  const detail::TranslationProducts tp = detail::translation_products(ch, &terms, p.q);
  const Eigen::Index d = ch.dofs(), N = p.T.rows();
  // tension = none: the tangent at rest (load factor 0, no multipliers) and the centrifugal
  // softening alone; tension = spin: the equilibrium's tangent holds it with the prestress.
  if (!tension) p.T.topLeftCorner(d, d) -= speed * speed * tp.mass;
  Matrix G = Matrix::Zero(N, N);
  G.topLeftCorner(d, d) = 2.0 * speed * tp.coriolis;
  Matrix Kr = p.Z.transpose() * p.T * p.Z, Mr = p.Z.transpose() * p.M * p.Z, Gr = p.Z.transpose() * G * p.Z;
  Kr = 0.5 * (Kr + Kr.transpose()).eval();
  Mr = 0.5 * (Mr + Mr.transpose()).eval();
  Gr = 0.5 * (Gr - Gr.transpose()).eval();
  const modal::GyroscopicModes gm = modal::gyroscopic_modes("multibody", Kr, Mr, Gr, count);
  ring::ModalResult res;
  res.solver = "multibody";
  res.model["n"] = static_cast<long long>(ch.n());
  res.model["rotary_inertia"] = options.rotary_inertia;
  res.model["theory"] = ring::to_string(spec.theory);
  res.model["dependent"] = ring::to_string(options.dependent);
  res.model["method"] = std::string("dense");
  res.unknowns = p.Z.cols();
  res.rigid_modes = 0;
  res.max_residual = gm.max_residual;
  res.residual_norm = ring::kResidual2Norm;
  res.frame = "rotating";
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto sample = [&](const Eigen::VectorXd& x) { return ch.shape_at(p.q, (p.Z * x).head(d)); };
  for (int k = 0; k < count; ++k) {
    auto [shape, wave] = modal::travelling_mode(gm.vectors.col(k), sample, speed);
    res.omega.push_back(gm.omega(k));
    res.shapes.push_back(std::move(shape));
    res.waves.push_back(wave);
  }
  return res;
}

ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                const ring::StaticOptions& statics) {
  check_static(spec, options, statics);
  const std::optional<double> loaded =
      statics.loads.points.empty() ? std::nullopt : std::optional<double>(statics.loads.points.front().angle);
  // static.displacement: the driven point is one more pin (held_spec) whose target moves.
  const ring::RingSpec held = detail::held_spec(spec, statics);
  std::optional<Eigen::Vector2d> drive;
  if (statics.displacement) drive = Eigen::Vector2d(statics.displacement->value[0], statics.displacement->value[1]);
  const Chain ch(held, options, loaded);
  const double depth = spec.section.depth();
  std::unique_ptr<detail::StaticEquilibrium> eq;
  if (backend(options, spec, statics) == Backend::banded)
    eq = natural::static_equilibrium(ch, held, statics.loads, depth, drive,
                                     statics.plates ? &*statics.plates : nullptr);
  else
    eq = detail::angle_equilibrium(ch, held, statics.loads, depth, drive,
                                   statics.plates ? &*statics.plates : nullptr);
  paths::Continuation policy;
  policy.steps = statics.steps;
  policy.history = statics.history;
  // A driven plastic chain: arc length from rest. Load stepping starts each Newton solve at the
  // last equilibrium with only the driven rows moved, and on the collapse plateau that first
  // iterate yields the neighbours of the mechanism's hinges too, whose zero tangent then cuts
  // the increments by halving (1878 equilibria on scenes/crushed-ring.toml at n = 80); the
  // arc's predictor follows the mechanism's own motion (as the lumped chain's statics do).
  // [plates] keep load steps, plastic too: the arc from rest stalled at approaches below ~1e-4 R
  // (its halvings ran out) and crawled on the plastic plateau (0.009 R in its 2000 steps at
  // n = 64), where load steps reach 5 collapse closings in 50 (test_plates.cpp).
  policy.from_start = statics.displacement.has_value() && spec.plastic.has_value();
  if (statics.path) {
    policy.branch_switch = true;
    policy.branch_side = statics.branch_side;
    std::vector<int> hinges;
    for (double a : statics.record) hinges.push_back(ch.hinge_at(a));
    eq->record_path(hinges);
  }
  const paths::Trace path = paths::follow(*eq, {eq->rest(), 0.0}, policy);
  const bool touched = statics.path && path.end == paths::Trace::End::contact;
  if (path.end != paths::Trace::End::reached && !touched)
    throw ring::NumericalError("multibody::solve_static: " + paths::failure_message(path, policy));
  ring::StaticResult res;
  if (statics.path) {
    res.path = eq->path();
    res.branch_points = path.branch_points;
    if (path.limit_state) res.limit_points.push_back(eq->point({path.limit_state->z, path.limit}));
    res.end = touched ? "contact: " + path.contact : statics.history.empty() ? "full load" : "end of the history";
    res.end_load = path.end_load;  // the touch, or the full load (a history: its last factor)
  }
  res.solver = "multibody";
  res.unknowns = eq->size();  // angles and multipliers, or positions and multipliers
  res.steps = path.steps;
  res.newton_iterations = path.iterations;
  const Eigen::Matrix2Xd hp = eq->hinges(path.state.z);
  for (double a : statics.record) {
    const int k = ch.hinge_at(a);
    const Eigen::Vector2d u = hp.col(k) - ch.hinge_rest(k);
    res.displacements.push_back({a, u.x(), u.y()});
  }
  res.dissipated = eq->dissipated();
  res.plastic_curvature = eq->plastic_curvature();
  res.reaction = eq->reaction(path.state.z);
  if (const auto p = eq->plates(path.state)) {
    res.reaction = p->reaction;
    res.contact_length = p->contact_length;
  }
  res.node_x.assign(hp.row(0).begin(), hp.row(0).end());
  res.node_y.assign(hp.row(1).begin(), hp.row(1).end());
  return res;
}

}  // namespace multibody
