// The statics of one discretization as an equilibrium path from rest (static_path.hpp;
// the method is documented in nonlinear.hpp, "Statics").
#include "fem_reference/static_path.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "fem_reference/beam_potential.hpp"
#include "fem_reference/newton.hpp"
#include "fem_reference/self_contact.hpp"
#include "modal/buckling.hpp"
#include "modal/inertia.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace fem::detail {
namespace {

/// No value of q (displacements at the support points) moves more than this fraction
/// of the radius in one step: arc steps, so that the path is resolved (a maximum and a
/// minimum of the load factor are never skipped together in one step); load steps, so
/// that Newton started just below a limit point cannot land on a distant branch.
constexpr double kMaxArcMove = 0.1;

/// The count of unstable directions (BeamEquilibrium::unstable_directions) is the inertia
/// of the assembled tangent by modal::frontal_inertia, a block LDL^T in the DoF order (the
/// DoFs follow the cells around the ring, so the tangent is a band whose closing corner the
/// front keeps as a border): O(N f^2), f the front (~ two cells' DoFs). Should the front
/// outgrow modal's bound, a dense symmetric eigen-solve (modal::unstable_directions)
/// counts it up to this many unknowns, O(N^3) (1500: ~1 s); nullopt above (no bifurcation
/// is detected).
constexpr unsigned int kDenseInertiaLimit = 1500;

/// [plates]' contact length: centroid-line points per cell (PlatePair::contact_lengths
/// interpolates the gap's zero between two of them, so the ends of the contact are found to
/// within the chord's sag and the gap's curvature over 1/32 of a cell).
constexpr unsigned int kContactPerCell = 32;

std::string number(double x, int digits = 9) {
  std::ostringstream o;
  o << std::setprecision(digits) << x;
  return o.str();
}

/// The path's point: the driven point, else the first point load's vertex, else the first
/// record point's, else vertex 0 (the pin, or 0 deg).
double path_point(const ring::StaticOptions& st) {
  if (st.displacement) return st.displacement->at;
  if (st.plates) return st.plates->axis;
  if (!st.loads.points.empty()) return st.loads.points.front().angle;
  if (!st.record.empty()) return st.record.front();
  return 0.0;
}

/// The beam's equilibrium grad V(q) - s grad Phi(q) = 0 (BeamPotential: the beam, its
/// terms and its loads) for the continuation driver: the bordered tangent
/// [K - s hess Phi, -grad Phi; w^T ws] assembled on one pattern (K's, plus a full last
/// row and column)
/// and factorized as a whole by UMFPACK (regular at a limit point, where K alone is
/// singular); self-contact checked along the chord between accepted equilibria.
/// ring.plastic: it holds the committed plastic state of every bending point of the beam
/// (plastic_points.hpp); every trial (linearize, tangent) is evaluated from them, and
/// accept() commits them at the accepted equilibrium, adding the step's plastic work.
///
/// The driven point (static.displacement, no loads): the vertex k's Cartesian displacement
/// G q = s v (G: 2 x N, whose transposed rows are BeamModel::vertex_force(k, e_x), (k, e_y):
/// the force's virtual work f . U_k = (G^T f) . q) is held by two Lagrange multipliers
/// lambda, the unknowns after q (arc_size() = N: the arc measures q only):
///   R_q = grad V(q) - G^T lambda = 0,   R_lambda = s v - G q = 0,
///   dR/ds = (0, v)  (the load column of the bordered matrix: the prescribed values),
/// and lambda is the force the rig applies to the ring there (PathPoint::reaction).
/// Multipliers rather than the supports' way (AffineConstraints eliminated from the reduced
/// numbering): an inhomogeneous line would need s inside the model's expand(), which every
/// term of both beams calls; the multipliers leave the models as they are, and the bordered
/// matrix [K -G^T dR/ds; -G 0 v; w^T 0 ws] stays regular (G has full rank on the vertex's
/// two free unknowns u, w). The constraints' tangent space is then q with those two unknowns
/// zero, on which the inertia and the critical direction are taken.
///
/// [plates] (no loads, no supports): the plates' penalty is a term of the potential
/// (BeamPotential: its energy, pressure, tangent and dR/ds = -F), and the two points of first
/// contact keep their place along the plates, e . U = 0 at the vertices at axis and
/// axis + 180 (e = (-sin axis, cos axis)), by the same two multipliers with v = 0: there e is
/// the vertex's own tangent t0 (or -t0), so each row holds one unknown, the vertex's u (G's
/// entries below 1e-12 of the largest, the rounding of cos and sin, are dropped so that the
/// constraints' tangent space stays q with those two unknowns zero). Their multipliers
/// (StaticPath::Point::no_slide) are the plates' friction that the ring would need: ~0 by
/// the crushing's symmetry. The reaction is the force of plate 0 (BeamPotential::Value).
class BeamEquilibrium : public paths::Equilibrium {
 public:
  BeamEquilibrium(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st, StaticSolve& out);
  Eigen::Index size() const override { return N_ + M_; }
  Eigen::Index arc_size() const override { return N_; }
  bool linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) override;
  bool solve(paths::Vector& y) override;
  /// Lengths (BeamModel::lengths: a rotation psi counts as R psi).
  double move(const paths::Vector& dz) const override { return model_.length_of(dz) / (kMaxArcMove * radius_); }
  /// No value of q changed by more than 1e-12 R, or (from the third iteration) the
  /// correction, below 1e-9 R, did not shrink: the rounding floor of a nearly singular
  /// tangent next to a bifurcation (its mode amplifies the residual's rounding), where the
  /// bisection of the bifurcation would stop otherwise (measured: brackets 3e-6 to 2e-4
  /// wide without this). Regular Newton contracts quadratically and never stalls above 1e-12 R.
  bool converged(const paths::State&, const paths::Vector& dz, int iteration) override {
    const double step = model_.length_of(dz);
    const bool stalled = iteration >= 3 && step >= last_step_ && step <= 1e-9 * radius_;
    last_step_ = step;
    return step <= 1e-12 * radius_ || stalled;
  }
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override;
  /// The negative eigenvalues of the tangent K - s hess Phi on the free unknowns (the
  /// supports are eliminated, so that space is the constraints' tangent space): see
  /// kDenseInertiaLimit.
  std::optional<int> unstable_directions(const paths::State& x) override;
  /// The eigenvector of the least eigenvalue of that tangent on the free unknowns (there
  /// are no multipliers): a dense symmetric eigen-solve, O(N^3), up to kDenseInertiaLimit
  /// unknowns; nullopt above (no branch switching: the path ends at the bifurcation).
  std::optional<paths::Vector> critical_direction(const paths::State& x) override;
  /// accept()'s self-contact measure at x: the closest approach of non-neighbouring
  /// parts of the deformed centreline minus the section depth; 0 while none comes within
  /// a depth (closest_approach looks no farther), negative once they have touched.
  /// O(2 pi R / depth) (the grid).
  std::optional<double> clearance(const paths::State& x) override {
    return closest_approach(model_.centreline(full(x.z), per_cell_), min_gap_, depth_, model_.open()).distance - depth_;
  }
  /// st.path: record ring::PathPoint in out.points (accept()).
  void record_path() {
    recording_ = true;
    for (double a : st_.record) record_vertices_.push_back(model_.vertex_of(a));
    out_.points.push_back(point_at(0.0, model_.expand(q_)));
  }
  /// The path point of an equilibrium (the located limit point).
  ring::PathPoint point_of(const paths::State& x) {
    ring::PathPoint pt = point_at(x.s, full(x.z));
    pt.reaction = reaction(x);
    pt.contact_length = contact_length(x);
    return pt;
  }
  /// The record and the deformed vertices at the end of a path that reached the full load
  /// (or, static.path, at its touching equilibrium).
  void finish(const paths::State& x);

 private:
  /// The tangent K - s hess Phi at x on the free unknowns, symmetrized; with a driven point
  /// on kept_ only (the constraints' tangent space).
  Eigen::SparseMatrix<double> tangent(const paths::State& x);
  /// The driven point's multipliers in z: the force on the ring there; [plates]: the force
  /// of the plate at plates.axis on the ring (BeamPotential::Value::plate_force); 0 without.
  std::array<double, 2> reaction(const paths::State& x) {
    if (st_.plates) {
      for (unsigned int i = 0; i < N_; ++i) q_[i] = x.z(i);
      return potential_.evaluate(q_, x.s, nullptr, nullptr, nullptr, committed()).plate_forces[0];
    }
    return multipliers(x.z);
  }
  std::array<double, 2> multipliers(const paths::Vector& z) const {
    return M_ ? std::array<double, 2>{z(N_), z(N_ + 1)} : std::array<double, 2>{0.0, 0.0};
  }
  /// [plates]: ring::PlatePair::contact_lengths of the deformed centroid line sampled at
  /// kContactPerCell points per cell in order around the ring; 0 without plates.
  std::array<double, 2> contact_length(const paths::State& x) const {
    if (!st_.plates) return {0.0, 0.0};
    const std::vector<Point2> line = model_.centreline(full(x.z), kContactPerCell);
    std::vector<double> X(line.size()), Y(line.size());
    for (std::size_t k = 0; k < line.size(); ++k) {
      X[k] = line[k][0];
      Y[k] = line[k][1];
    }
    return potential_.plates()->contact_lengths(X, Y, x.s);
  }
  /// The path point of the full DoF vector q at load factor s: the displacements of the
  /// record vertices; the ovalisation (largest - smallest distance between opposite
  /// vertices k and k + cells / 2; with an odd count of cells the nearest to opposite, as
  /// the chains do) / R.
  ring::PathPoint point_at(double s, const Vector<double>& q) const;
  /// The committed plastic states for BeamPotential::evaluate; null without ring.plastic.
  const std::vector<ring::PlasticState>* committed() const { return law_ ? &plastic_ : nullptr; }
  Vector<double> full(const paths::Vector& z) const {
    Vector<double> q(N_);
    for (unsigned int i = 0; i < N_; ++i) q[i] = z(i);
    return model_.expand(q);
  }

  const ring::RingSpec& spec_;
  const ring::StaticOptions& st_;
  const std::unique_ptr<BeamModel> built_;
  const BeamModel& model_;
  const unsigned int N_;
  const unsigned int M_;  ///< multipliers: 2 with a driven point, else 0
  const unsigned int loaded_;
  /// The driven point: the rows of G as (unknown, value) pairs, the prescribed v at s = 1,
  /// and the unknowns kept on the constraints' tangent space (all N without one).
  std::array<std::vector<std::pair<unsigned int, double>>, 2> G_;
  std::array<double, 2> v_{0.0, 0.0};
  std::vector<unsigned int> kept_;
  const BeamPotential potential_;
  const std::optional<PlasticLaw>& law_;  ///< ring.plastic's, or nullopt
  std::vector<ring::PlasticState> plastic_;      ///< committed, per bending point
  double dissipated_ = 0.0;                      ///< plastic work from rest, J
  double plastic_curvature_ = 0.0;               ///< largest |kappa_p| now, 1/m
  Vector<double> F_;  ///< grad Phi at the last linearization: the load, dR/ds = -F
  const double radius_, depth_;  ///< depth: the self-contact distance
  unsigned int per_cell_ = 2;    ///< centreline points per cell (spacing <= depth / 2)
  double last_step_ = 0.0;       ///< the Newton correction before (converged's memory)
  int min_gap_ = 2;              ///< centreline edges closer along the ring are neighbours
  SparsityPattern pattern_;
  SparseMatrix<double> B_;
  Vector<double> q_, r_, y_;
  NewtonLu lu_;  ///< the bordered Newton matrix's LU
  std::vector<Point2> last_centreline_;
  bool recording_ = false;
  std::vector<unsigned int> record_vertices_;
  StaticSolve& out_;
};

BeamEquilibrium::BeamEquilibrium(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                                 StaticSolve& out)
    : spec_(spec),
      st_(st),
      built_(make_beam(spec, setup)),
      model_(*built_),
      N_(model_.n_free()),
      M_(st.displacement || st.plates ? 2 : 0),
      loaded_(model_.vertex_of(path_point(st))),
      potential_(model_, st.loads, true, st.plates ? &*st.plates : nullptr),
      law_(potential_.plastic_law()),
      radius_(spec.radius),
      depth_(spec.section.depth()),
      q_(N_),
      out_(out) {
  // Centreline points at most depth / 2 apart along the rest ring (chord sag of a part
  // bent to radius rho: spacing^2 / (8 rho), far below the depth); edges whose nearest
  // ends are at least 2 depths apart along the ring are "not neighbours": bending alone
  // would need a radius below the depth to bring those within a depth of each other.
  const double cell_arc = spec.opening() * spec.radius / model_.cells();
  per_cell_ = std::max(2u, static_cast<unsigned int>(std::ceil(cell_arc / (0.5 * depth_))));
  min_gap_ = 1 + static_cast<int>(std::ceil(2.0 * depth_ / (cell_arc / per_cell_)));
  std::vector<bool> held(N_, false);
  if (st.displacement) {
    v_ = st.displacement->value;
    for (unsigned int c = 0; c < 2; ++c) {
      const Vector<double> g = model_.vertex_force(loaded_, {c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0});
      for (unsigned int i = 0; i < N_; ++i)
        if (g[i] != 0.0) {
          G_[c].emplace_back(i, g[i]);
          held[i] = true;
        }
    }
    // The vertex's u and w are free unknowns of their own (check_static keeps supports off
    // it), so G is a rotation on those two: its kernel is q with them zero.
    if (std::count(held.begin(), held.end(), true) != 2)
      throw std::logic_error("fem statics: the driven vertex does not have two free unknowns of its own");
  }
  if (st.plates) {
    // The no-slide rows (class comment): e . U at the vertices at axis and axis + 180.
    const double a = st.plates->axis * M_PI / 180.0;
    const std::array<double, 2> e{-std::sin(a), std::cos(a)};
    for (unsigned int c = 0; c < 2; ++c) {
      const Vector<double> g = model_.vertex_force(model_.vertex_of(st.plates->axis + 180.0 * c), e);
      const double largest = g.linfty_norm();
      for (unsigned int i = 0; i < N_; ++i)
        if (std::abs(g[i]) > 1e-12 * largest) {
          G_[c].emplace_back(i, g[i]);
          held[i] = true;
        }
    }
    if (std::count(held.begin(), held.end(), true) != 2)
      throw std::logic_error("fem statics: the plates' no-slide rows do not hold one free unknown each");
  }
  for (unsigned int i = 0; i < N_; ++i)
    if (!held[i]) kept_.push_back(i);
  const unsigned int L = N_ + M_;  // the bordered matrix's last row and column
  DynamicSparsityPattern dsp(L + 1, L + 1);
  for (auto e = model_.sparsity().begin(); e != model_.sparsity().end(); ++e) dsp.add(e->row(), e->column());
  for (unsigned int c = 0; c < M_; ++c)
    for (const auto& [i, g] : G_[c]) {
      dsp.add(i, N_ + c);
      dsp.add(N_ + c, i);
    }
  for (unsigned int i = 0; i <= L; ++i) {
    dsp.add(i, L);
    dsp.add(L, i);
  }
  pattern_.copy_from(dsp);
  B_.reinit(pattern_);
  out_.unknowns = N_;
  out_.path.push_back({0.0, {0.0, 0.0}});
  if (law_) plastic_.assign(potential_.plastic_states(), ring::PlasticState{});
  last_centreline_ = model_.centreline(model_.expand(q_), per_cell_);
}

bool BeamEquilibrium::linearize(const paths::State& x, const paths::Vector& w, double ws, paths::Vector& r) {
  for (unsigned int i = 0; i < N_; ++i) q_[i] = x.z(i);
  potential_.evaluate(q_, x.s, &r_, &B_, &F_, committed());  // K in the top-left block, border zeroed
  const unsigned int L = N_ + M_;
  for (unsigned int i = 0; i < N_; ++i) {
    B_.set(i, L, -F_[i]);
    B_.set(L, i, w(i));
  }
  B_.set(L, L, ws);
  r.resize(L);
  for (unsigned int i = 0; i < N_; ++i) r(i) = r_[i];
  // The driven point (class comment): -G^T lambda in R_q, s v - G q, and their columns.
  for (unsigned int c = 0; c < M_; ++c) {
    const double lambda = x.z(N_ + c);
    double Gq = 0.0;
    for (const auto& [i, g] : G_[c]) {
      r(i) -= g * lambda;
      Gq += g * x.z(i);
      B_.set(i, N_ + c, -g);
      B_.set(N_ + c, i, -g);
    }
    r(N_ + c) = x.s * v_[c] - Gq;
    B_.set(N_ + c, L, v_[c]);
  }
  if (!r.allFinite()) return false;
  try {
    lu_.initialize(B_);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

bool BeamEquilibrium::solve(paths::Vector& y) {
  const unsigned int L = N_ + M_;
  y_.reinit(L + 1);
  for (unsigned int i = 0; i <= L; ++i) y_[i] = y(i);
  lu_.solve(y_);
  for (unsigned int i = 0; i <= L; ++i) y(i) = y_[i];
  return y.allFinite();
}

std::optional<paths::Touch> BeamEquilibrium::accept(const paths::State&, const paths::State& to) {
  const Vector<double> q = full(to.z);
  StaticPath::Point at_path{to.s, model_.vertex_displacement(q, loaded_)};
  at_path.reaction = multipliers(to.z);
  if (st_.plates) at_path.no_slide = multipliers(to.z);
  at_path.contact_length = contact_length(to);
  for (unsigned int i = 0; i < N_; ++i) q_[i] = to.z(i);
  if (law_) {
    // Commit before anything else: a touch ends the path at this equilibrium too.
    const std::vector<BendingPoint> bp = model_.bending_points(q_, Plasticity{*law_, plastic_});
    const Committed step = commit(*law_, bp, plastic_);
    dissipated_ += step.dissipated;
    plastic_curvature_ = step.largest_plastic;
    out_.dissipated = dissipated_;
    out_.plastic_curvature = plastic_curvature_;
    at_path.dissipated = dissipated_;
  }
  if (law_ || M_) {
    // The energies at the committed state (a driven path's rig work is set against them).
    // V and Phi do not depend on s; the plates' penalty does (its gap).
    const BeamPotential::Value v = potential_.evaluate(q_, to.s, nullptr, nullptr, nullptr, committed());
    at_path.stored = v.stored;
    at_path.load = v.load;
    if (st_.plates) {
      at_path.reaction = v.plate_forces[0];
      at_path.opposite = v.plate_forces[1];
      const bool off = at_path.reaction == std::array<double, 2>{0.0, 0.0} ||
                       at_path.opposite == std::array<double, 2>{0.0, 0.0};
      out_.left_plates = off ? to.s : std::numeric_limits<double>::quiet_NaN();
    }
  }
  out_.path.push_back(at_path);
  if (recording_) {
    out_.points.push_back(point_at(to.s, q));
    out_.points.back().dissipated = dissipated_;
    out_.points.back().plastic_curvature = plastic_curvature_;
    out_.points.back().reaction = at_path.reaction;
    out_.points.back().contact_length = at_path.contact_length;
  }
  std::vector<Point2> next = model_.centreline(q, per_cell_);
  // The deformed centreline moves between the two equilibria; checking only the ends
  // could miss a part passing through another, so the chord between them is checked at
  // sub-steps that move no point by more than depth / 2 (two parts then close in by at
  // most a depth per sub-step, and a crossing counts as distance 0).
  double move = 0.0;
  for (std::size_t k = 0; k < next.size(); ++k)
    move = std::max(move, std::hypot(next[k][0] - last_centreline_[k][0], next[k][1] - last_centreline_[k][1]));
  const int substeps = std::max(1, static_cast<int>(std::ceil(move / (0.5 * depth_))));
  std::vector<Point2> at(next.size());
  for (int j = 1; j <= substeps; ++j) {
    const double w = static_cast<double>(j) / substeps;
    for (std::size_t k = 0; k < next.size(); ++k)
      for (int c = 0; c < 2; ++c) at[k][c] = last_centreline_[k][c] + w * (next[k][c] - last_centreline_[k][c]);
    const Approach a = closest_approach(at, min_gap_, depth_, model_.open());
    if (a.first >= 0 && a.distance < depth_) {
      const double pin = spec_.anchor();
      const double edges = model_.open() ? at.size() - 1.0 : at.size();
      const double span = spec_.is_arch() ? spec_.arc->span() : 360.0;
      auto angle = [&](int edge) { return ring::wrap_degrees(pin + (edge + 0.5) * span / edges); };
      return paths::Touch{w, "the centreline near " + number(angle(a.first), 4) + " deg and near " +
                                 number(angle(a.second), 4) + " deg (rest positions) " +
                                 (a.distance == 0.0 ? std::string("crosses itself")
                                                    : "comes within " + number(a.distance, 4) + " m of itself") +
                                 " (section depth " + number(depth_, 6) +
                                 " m); the beam model does not include contact"};
    }
  }
  last_centreline_ = std::move(next);
  return std::nullopt;
}

Eigen::SparseMatrix<double> BeamEquilibrium::tangent(const paths::State& x) {
  for (unsigned int i = 0; i < N_; ++i) q_[i] = x.z(i);
  SparseMatrix<double> T(pattern_);
  potential_.evaluate(q_, x.s, nullptr, &T, nullptr, committed());
  // kept_'s position of each unknown (-1: a driven one, off the constraints' tangent space).
  std::vector<int> at(N_, -1);
  for (unsigned int k = 0; k < kept_.size(); ++k) at[kept_[k]] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> t;
  for (auto e = T.begin(); e != T.end(); ++e)
    if (e->row() < N_ && e->column() < N_ && e->value() != 0.0 && at[e->row()] >= 0 && at[e->column()] >= 0)
      t.emplace_back(at[e->row()], at[e->column()], e->value());
  const Eigen::Index n = static_cast<Eigen::Index>(kept_.size());
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  K = (0.5 * (K + Eigen::SparseMatrix<double>(K.transpose()))).eval();
  return K;
}

std::optional<int> BeamEquilibrium::unstable_directions(const paths::State& x) {
  const Eigen::SparseMatrix<double> K = tangent(x);
  const Eigen::Index n = K.rows();
  std::vector<std::vector<int>> groups(n);
  for (Eigen::Index i = 0; i < n; ++i) groups[i] = {static_cast<int>(i)};
  if (const auto in = modal::frontal_inertia(K, groups, {}); in && in->zero == 0) return static_cast<int>(in->negative);
  if (N_ > kDenseInertiaLimit) return std::nullopt;
  return modal::unstable_directions(Eigen::MatrixXd(K), Eigen::MatrixXd(0, n));
}

std::optional<paths::Vector> BeamEquilibrium::critical_direction(const paths::State& x) {
  if (N_ > kDenseInertiaLimit) return std::nullopt;
  const Eigen::MatrixXd K(tangent(x));
  const Eigen::VectorXd d = modal::least_stable(K, Eigen::MatrixXd(0, K.rows())).direction;
  paths::Vector out = paths::Vector::Zero(N_ + M_);  // the driven unknowns and multipliers: 0
  for (std::size_t k = 0; k < kept_.size(); ++k) out(kept_[k]) = d(static_cast<Eigen::Index>(k));
  return out;
}

ring::PathPoint BeamEquilibrium::point_at(double s, const Vector<double>& q) const {
  ring::PathPoint pt;
  pt.load_factor = s;
  for (std::size_t i = 0; i < record_vertices_.size(); ++i) {
    const auto u = model_.vertex_displacement(q, record_vertices_[i]);
    pt.displacements.push_back({st_.record[i], u[0], u[1]});
  }
  const unsigned int n = model_.cells();
  auto at = [&](unsigned int k) {
    const auto X = model_.vertex_position(k);
    const auto u = model_.vertex_displacement(q, k);
    return std::array<double, 2>{X[0] + u[0], X[1] + u[1]};
  };
  double most = 0.0, least = HUGE_VAL;
  // An arch has no opposite vertices: its ovalisation stays 0.
  for (unsigned int k = 0; k < (model_.open() ? 0 : (n + 1) / 2); ++k) {
    const auto a = at(k), b = at((k + n / 2) % n);
    const double d = std::hypot(a[0] - b[0], a[1] - b[1]);
    most = std::max(most, d);
    least = std::min(least, d);
  }
  pt.ovalisation = model_.open() ? 0.0 : (most - least) / radius_;
  const unsigned int vertices = model_.vertices();
  for (unsigned int k = 0; k < vertices; k += static_cast<unsigned int>(ring::path_shape_stride(vertices))) {
    const auto p = at(k);
    pt.node_x.push_back(p[0]);
    pt.node_y.push_back(p[1]);
  }
  return pt;
}

void BeamEquilibrium::finish(const paths::State& x) {
  const paths::Vector& z = x.z;
  const Vector<double> q = full(z);
  out_.reaction = reaction(x);
  out_.contact_length = contact_length(x);
  for (double a : st_.record) out_.record.push_back(model_.vertex_displacement(q, model_.vertex_of(a)));
  for (unsigned int k = 0; k < model_.vertices(); ++k) {
    const auto X = model_.vertex_position(k);
    const auto u = model_.vertex_displacement(q, k);
    out_.node_x.push_back(X[0] + u[0]);
    out_.node_y.push_back(X[1] + u[1]);
  }
}

}  // namespace

StaticSolve trace_path(const ring::RingSpec& spec, const Setup& setup, const ring::StaticOptions& st,
                       const ContinuationOptions& continuation) {
  StaticSolve out;
  BeamEquilibrium beam(spec, setup, st, out);
  paths::Continuation options = continuation;
  options.steps = st.steps;
  options.history = st.history;
  // A driven plastic beam: arc length from rest, as the chains do (load stepping's first
  // iterate on the collapse plateau yields more points than the mechanism's and the increments
  // halve: 5713 equilibria on scenes/crushed-ring.toml at 40 cells of degree 5).
  options.from_start = continuation.from_start || (st.driven() && spec.plastic.has_value());
  if (st.path) {
    options.branch_switch = true;
    options.branch_side = st.branch_side;
    beam.record_path();
  }
  out.trace = paths::follow(beam, {paths::Vector::Zero(beam.size()), 0.0}, options);
  if (out.reached() || (st.path && out.trace.end == paths::Trace::End::contact)) beam.finish(out.trace.state);
  if (st.path && out.trace.limit_state) out.limits.push_back(beam.point_of(*out.trace.limit_state));
  return out;
}

std::string failure_message(const StaticSolve& s, const ContinuationOptions& continuation) {
  std::string why = "fem statics: " + paths::failure_message(s.trace, continuation);
  if (!std::isnan(s.left_plates))
    why += "; the ring had left a plate at load factor " + number(s.left_plates) +
           " (the plates backed off past its springback, and a ring off a plate has no equilibrium position "
           "along the plates' normal): end the history before the force falls to 0";
  return why;
}

}  // namespace fem::detail
