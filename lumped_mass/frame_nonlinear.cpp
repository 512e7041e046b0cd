// Statics and response of the corotational Timoshenko frame (frame.hpp): the frame's model
// in the shared drivers (paths/continuation.hpp, paths/time_stepping.hpp), as nonlinear.cpp
// does for the chain. nonlinear.hpp states the contract and what is offered.
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "lumped_mass/checks.hpp"
#include "lumped_mass/frame.hpp"
#include "lumped_mass/midpoint.hpp"
#include "lumped_mass/stability.hpp"
#include "modal/buckling.hpp"
#include "paths/continuation.hpp"
#include "paths/time_stepping.hpp"
#include "ring/energy_guard.hpp"
#include "ring/errors.hpp"

namespace lumped {
namespace {

using Vec = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;
using Sparse = Eigen::SparseMatrix<double>;
using LU = Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>>;

/// The support rows S as triplets at (row_offset + row, col) times `scale`, and transposed.
void support_triplets(const Frame& f, int row_offset, double scale, Triplets& out) {
  for (int c = 0; c < f.S.outerSize(); ++c)
    for (Sparse::InnerIterator it(f.S, c); it; ++it) {
      out.emplace_back(row_offset + static_cast<int>(it.row()), c, scale * it.value());
      out.emplace_back(c, row_offset + static_cast<int>(it.row()), scale * it.value());
    }
}

/// The largest change of an element's chord direction (|d(x_{j+1} - x_j)| / l, rad to first
/// order) or of a section rotation in dq, against half a radian (the chain's basin).
double frame_move(const Frame& f, const Vec& dq) {
  double turn = 0.0;
  for (int j = 0; j < f.n; ++j) {
    const int a = 3 * j, b = 3 * ((j + 1) % f.n);
    turn = std::max({turn, std::hypot(dq[b] - dq[a], dq[b + 1] - dq[a + 1]) / f.l, std::abs(dq[a + 2])});
  }
  return turn / 0.5;
}

/// The size of a Newton correction: the largest node movement and R times the largest
/// rotation change, m.
double correction_size(const Frame& f, const Vec& dq, double radius) {
  double m = 0.0;
  for (int j = 0; j < f.n; ++j)
    m = std::max({m, std::abs(dq[3 * j]), std::abs(dq[3 * j + 1]), radius * std::abs(dq[3 * j + 2])});
  return m;
}

/// [plates] on the frame: the chain's penalty (chain.hpp, add_plates) on the node positions,
/// f.geometry the chain's view of them (its plates, l, rho and rest), mapped to q (3 per node,
/// the translations first). Nothing without plates. O(n).
void add_frame_plates(const Frame& f, const Vec& q, double s, double hess_scale, Springs& out) {
  if (!f.geometry.plates) return;
  Springs p;
  p.grad = Vec::Zero(2 * f.n);
  add_plates(f.geometry, f.positions(q), s, hess_scale, p);
  out.energy += p.energy;
  for (int j = 0; j < f.n; ++j) out.grad.segment<2>(3 * j) += p.grad.segment<2>(2 * j);
  for (const auto& t : p.hess)
    out.hess.emplace_back(3 * (t.row() / 2) + t.row() % 2, 3 * (t.col() / 2) + t.col() % 2, t.value());
}

/// The frame's equilibrium grad V(q) + S^T mu + s grad P(q) = 0, S (q - rest) = 0, for the
/// continuation driver. Unknowns z = (q, mu), mu in units of the frame's scale EI / l^3 (the
/// rows balanced against the stiffness for the LU's pivoting), the bordered KKT matrix by
/// factor_bordered (chain.hpp, shared with the chain's statics). The arc length is measured
/// on all of q (positions in m, rotations in rad). A bifurcation ends the path (dense count,
/// up to n = 133); no branch switching; the self-contact check is the chain's on the chords.
/// ring.plastic: the elements' bending law (bending.hpp) would live in this equilibrium's own
/// copy of the frame, whose states accept() commits (as the chain's statics do; the frames
/// refuse the law for now, checks.cpp); an elastic frame is not copied.
class FrameStatics : public paths::Equilibrium {
 public:
  FrameStatics(const Frame& f, const FrameLoads& loads, double radius)
      : own_(f.bending.plastic() ? std::optional<Frame>(f) : std::nullopt),
        f_(own_ ? *own_ : f),
        L_(loads),
        N_(3 * f.n),
        E_(f.geometry.plates ? 1 : 0),
        S_(3 * f.n + E_ + static_cast<int>(f.S.rows())),
        radius_(radius),
        rate_(Vec::Zero(f.S.rows())) {
    if (f.driven >= 0) rate_.tail(2) = -f.drive;
  }
  FrameStatics(const FrameStatics&) = delete;  // f_ may refer to own_
  FrameStatics& operator=(const FrameStatics&) = delete;
  Eigen::Index size() const override { return S_; }
  /// q, and with [plates] their advance a (the chain's statics say why).
  Eigen::Index arc_size() const override { return N_ + E_; }
  bool linearize(const paths::State& s, const paths::Vector& w, double ws, paths::Vector& r) override {
    const Vec q = s.z.head(N_), mu = multipliers(s.z) * f_.scale;
    const int M = N_ + E_;  // the first multiplier's row
    Springs sp = frame_energy(f_, q, 1.0);
    add_frame_plates(f_, q, s.s, 1.0, sp);
    L_.add_hessian(q, s.s, sp.hess);
    support_triplets(f_, M, f_.scale, sp.hess);
    const Vec gP = L_.gradient(q);
    r.resize(S_);
    r.head(N_) = sp.grad + f_.S.transpose() * mu + s.s * gP;
    // A driven point (static.displacement): its rows S (q - rest) - s drive; rate_ = their
    // change with s, the load column's constraint part (no loads act then: gP = 0).
    r.tail(S_ - M) = f_.scale * (f_.S * (q - f_.rest) + s.s * rate_);
    Vec b = Vec::Zero(S_), wz = Vec::Zero(S_);
    b.head(N_) = gP;
    b.tail(S_ - M) = f_.scale * rate_;
    if (f_.geometry.plates) {  // the chain's load column and advance row (nonlinear.cpp)
      const Vec rate = plate_rate(f_.geometry, f_.positions(q), s.s);
      for (int j = 0; j < f_.n; ++j) b.segment<2>(3 * j) += rate.segment<2>(2 * j);
      const double half = 0.5 * f_.geometry.plates->travel;
      r[N_] = f_.scale * (s.z[N_] - s.s * half);
      sp.hess.emplace_back(N_, N_, f_.scale);
      b[N_] = -f_.scale * half;
    }
    wz.head(M) = w.head(M);
    return factor_bordered(std::move(sp.hess), S_, b, wz, ws, lu_) && r.allFinite();
  }
  bool solve(paths::Vector& y) override {
    y = lu_.solve(y).eval();
    return y.allFinite();
  }
  double move(const paths::Vector& dz) const override { return frame_move(f_, dz.head(N_)); }
  /// No node moved by more than 1e-12 R (nor a section turned by more than 1e-12 rad), or,
  /// from the third iteration, the correction (below 1e-9 R) did not shrink: the rounding
  /// floor of the stiff axial rows (the chain's rule).
  bool converged(const paths::State&, const paths::Vector& dz, int iteration) override {
    const double step = correction_size(f_, dz.head(N_), radius_);
    const bool stalled = iteration >= 3 && step >= last_step_ && step <= 1e-9 * radius_;
    last_step_ = step;
    return step <= 1e-12 * radius_ || stalled;
  }
  /// The tangent's unstable directions on ker S (modal::unstable_directions, dense: the
  /// eigenvalues of Z^T T Z), for the driver's bifurcation test, while 3n <= the chain's
  /// kDenseInertiaUnknowns (stability.hpp; O(n^3)); none above: no bifurcation is detected.
  std::optional<int> unstable_directions(const paths::State& s) override {
    if (N_ > kDenseInertiaUnknowns) return std::nullopt;
    Springs sp = frame_energy(f_, s.z.head(N_), 1.0);
    add_frame_plates(f_, s.z.head(N_), s.s, 1.0, sp);
    L_.add_hessian(s.z.head(N_), s.s, sp.hess);
    Sparse T(N_, N_);
    T.setFromTriplets(sp.hess.begin(), sp.hess.end());
    return modal::unstable_directions(Eigen::MatrixXd(T), Eigen::MatrixXd(f_.S));
  }
  /// Commits the elements' bending states at `to` and adds the step's work of the loads (the
  /// trapezoidal rule, as the chain's statics), then the self-contact check.
  std::optional<paths::Touch> accept(const paths::State& from, const paths::State& to) override {
    work_ -= 0.5 * (from.s + to.s) * (L_.potential(to.z.head(N_)) - L_.potential(from.z.head(N_)));
    if (f_.driven >= 0) {  // the rig's work, the trapezoidal rule (the chain's statics)
      const std::array<double, 2> a = reaction(from.z, from.s), b = reaction(to.z, to.s);
      work_ += 0.5 * (to.s - from.s) * ((a[0] + b[0]) * f_.drive.x() + (a[1] + b[1]) * f_.drive.y());
    }
    if (f_.geometry.plates) {  // the plates' work (the chain's statics)
      const std::array<double, 2> a = plate_loads(f_.geometry, f_.positions(from.z.head(N_)), from.s),
                                  b = plate_loads(f_.geometry, f_.positions(to.z.head(N_)), to.s);
      work_ += 0.5 * (to.s - from.s) * 0.5 * f_.geometry.plates->travel * (a[0] + a[1] + b[0] + b[1]);
    }
    if (own_) own_->bending.commit(bending_strains(f_, to.z.head(N_)));
    const Contact k = closest_nonadjacent(f_.geometry, f_.positions(to.z.head(N_)));
    if (k.distance >= f_.geometry.depth) return std::nullopt;
    return paths::Touch{1.0, contact_where(f_.geometry, k) + "; the frame model does not include contact"};
  }

  /// The multipliers of z (the support rows), in units of f_.scale.
  Vec multipliers(const paths::Vector& z) const { return z.tail(S_ - N_ - E_); }
  /// The path's energies so far, the elastic energy at q (and the plates' penalty at s).
  FramePathEnergy energy(const Vec& q, double s) const {
    FramePathEnergy e;
    e.dissipated = f_.bending.dissipated();
    e.plastic_curvature = f_.bending.plastic_curvature();
    e.work = work_;
    // The incremental potential at the committed states' own strains is the stored energy.
    Springs sp = frame_energy(f_, q, 0.0);
    add_frame_plates(f_, q, s, 0.0, sp);
    e.stored = sp.energy;
    if (f_.geometry.plates) e.contact_length = plate_contact_lengths(f_.geometry, f_.positions(q), s);
    return e;
  }
  /// The force the rig applies on the frame at the driven node, N: minus its rows'
  /// multipliers (S's last two); [plates]: the force of the plate at plates.axis on the ring.
  /// 0 without either.
  std::array<double, 2> reaction(const paths::Vector& z, double s) const {
    if (f_.geometry.plates) {
      const double F = plate_loads(f_.geometry, f_.positions(z.head(N_)), s)[0];
      return {-F * f_.geometry.plates->d[0], -F * f_.geometry.plates->d[1]};
    }
    if (f_.driven < 0) return {0.0, 0.0};
    return {-f_.scale * z[S_ - 2], -f_.scale * z[S_ - 1]};
  }

 private:
  std::optional<Frame> own_;  ///< ring.plastic: a copy, whose bending states are this path's
  const Frame& f_;            ///< own_, or the caller's elastic frame
  const FrameLoads& L_;
  const int N_, E_, S_;  ///< q; 1 with [plates] (their advance), else 0; all unknowns
  const double radius_;
  double last_step_ = INFINITY;
  double work_ = 0.0;  ///< the loads' work along the accepted path, and the rig's, J
  Vec rate_;           ///< d(S (q - rest) - target) / ds: -drive on a driven point's rows, else 0
  LU lu_;
};

std::vector<int> record_nodes(const Frame& f, const std::vector<double>& record, const std::string& key) {
  std::vector<int> h;
  for (double a : record) h.push_back(node_of(a, f.geometry.anchor_deg, f.n, key));
  return h;
}

}  // namespace

paths::Trace frame_path(const Frame& f, const FrameLoads& loads, double radius, const ring::StaticOptions& statics,
                        const std::string& who, FramePathEnergy* energy) {
  const int N = 3 * f.n;
  FrameStatics eq(f, loads, radius);
  paths::State rest{paths::Vector::Zero(eq.size()), 0.0};
  rest.z.head(N) = f.rest;
  paths::Continuation policy;
  policy.steps = statics.steps;
  policy.history = statics.history;
  paths::Trace path = paths::follow(eq, rest, policy);
  if (path.end != paths::Trace::End::reached)
    throw ring::NumericalError(who + ": " + paths::failure_message(path, policy));
  if (energy) {
    *energy = eq.energy(path.state.z.head(N), path.state.s);
    energy->reaction = eq.reaction(path.state.z, path.state.s);
  }
  return path;
}

namespace {

/// [plates] on the frame: the plates on f.geometry (the chain's view of its nodes) and the
/// chain's three rows on q's translations (chain.hpp, hold_plates), appended to f.S.
void hold_frame_plates(Frame& f, const ring::RingSpec& spec, const ring::StaticOptions::Plates& plates) {
  f.geometry.plates.emplace(spec, plates);
  const std::array<int, 2> nodes{node_of(plates.axis, f.geometry.anchor_deg, f.n, "plates.axis"),
                                 node_of(plates.axis + 180.0, f.geometry.anchor_deg, f.n, "plates.axis")};
  f.geometry.plate_nodes = nodes;
  const std::array<double, 2> d = f.geometry.plates->d, e{-d[1], d[0]};
  Triplets t;
  for (int col = 0; col < f.S.outerSize(); ++col)
    for (Sparse::InnerIterator it(f.S, col); it; ++it) t.emplace_back(static_cast<int>(it.row()), col, it.value());
  const int r = static_cast<int>(f.S.rows());
  for (int p = 0; p < 2; ++p)
    for (int i = 0; i < 2; ++i) {
      t.emplace_back(r + p, 3 * nodes[p] + i, e[i]);
      t.emplace_back(r + 2, 3 * nodes[p] + i, d[i]);
    }
  Sparse S(r + 3, f.S.cols());
  S.setFromTriplets(t.begin(), t.end());
  f.S = S;
}

}  // namespace

StaticDetail frame_static(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                          const ring::StaticOptions& statics) {
  const auto t0 = std::chrono::steady_clock::now();
  Frame f = make_frame(spec, options);
  const Sparse supports = f.S;  // the ground's rows (ground_force), without a driven point's
  if (statics.displacement) {
    f.driven = node_of(statics.displacement->at, f.geometry.anchor_deg, f.n, "static.displacement.at");
    f.drive = Vec2(statics.displacement->value[0], statics.displacement->value[1]);
    f.S = with_point_rows(f.S, 3 * f.driven);
  }
  if (statics.plates) hold_frame_plates(f, spec, *statics.plates);
  const FrameLoads loads(f, spec, statics.loads, "static");
  const auto rec = record_nodes(f, statics.record, "static.record");
  const int N = 3 * f.n, R = static_cast<int>(f.S.rows());
  FramePathEnergy energy;
  const paths::Trace path =
      frame_path(f, loads, spec.radius, statics, "lumped statics (" + ring::to_string(options.variant) + ")", &energy);
  const Vec q = path.state.z.head(N), mu = path.state.z.tail(R) * f.scale;
  StaticDetail detail;
  ring::StaticResult& out = detail.result;
  out.dissipated = energy.dissipated;
  out.plastic_curvature = energy.plastic_curvature;
  detail.work = energy.work;
  detail.stored = energy.stored;
  out.steps = path.steps;
  out.newton_iterations = path.iterations;
  for (std::size_t p = 0; p < rec.size(); ++p) {
    const int k = rec[p];
    out.displacements.push_back({statics.record[p], q[3 * k] - f.rest[3 * k], q[3 * k + 1] - f.rest[3 * k + 1]});
  }
  for (int j = 0; j < f.n; ++j) {
    out.node_x.push_back(q[3 * j]);
    out.node_y.push_back(q[3 * j + 1]);
  }
  detail.ground_force = ground_force(supports, mu.head(supports.rows()), *f.terms, q - f.rest, 3);
  out.reaction = energy.reaction;
  out.contact_length = energy.contact_length;
  if (statics.plates) {  // the chain's three rows, S's last
    detail.no_slide = {mu[R - 3], mu[R - 2]};
    detail.centre = mu[R - 1];
    detail.plate_loads = plate_loads(f.geometry, f.positions(q), path.state.s);
  }
  out.solver = "lumped";
  out.unknowns = N + R + (statics.plates ? 1 : 0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return detail;
}

namespace {

/// The frame's implicit midpoint step (midpoint.hpp) on (q, mu), the constraint rows
/// S (q_1 - rest) = 0 with the forces S^T mu: the chain's scheme without link constraints. The
/// supports are linear, so they hold to round-off and do no work; the balance error is the
/// midpoint rule's O(h^2) on the non-quadratic element energy and the follower and central
/// pressures. The point inertias' J sits in the constant mass on th (exact).
class FrameStepper : public detail::MidpointStepper {
 public:
  FrameStepper(const Frame& f, const ring::ResponseOptions& r, double radius, const FrameLoads& loads, Sparse C,
               std::vector<int> rec)
      : MidpointStepper(r, f.M, std::move(C), f.rest, f.S.rows()), f_(f), radius_(radius), L_(loads),
        rec_(std::move(rec)) {}

  void shape(std::vector<double>& x, std::vector<double>& y) const override {
    paths::interleaved_shape(f_.positions(q_), f_.n, x, y);
  }

  std::optional<std::string> contact() const override {
    const Contact k = closest_nonadjacent(f_.geometry, f_.positions(q_));
    if (k.distance >= f_.geometry.depth) return std::nullopt;
    return contact_where(f_.geometry, k);
  }

 private:
  // The Newton system of the step (paths/newton.hpp) on (q1_, mu1_), full Newton with the
  // sparse LU: the basin is frame_move's, converged when the correction moves no node by more
  // than 1e-11 R and turns no section by more than 1e-11 rad.
  paths::Rule rule() const override {
    paths::Rule r;
    r.tolerance = 1e-11 * radius_;
    return r;
  }
  bool linearize(bool) override {
    const double hh = step_size(), factor = load_factor();
    const int N = 3 * f_.n, R = static_cast<int>(f_.S.rows());
    const double scale = 2.0 / (hh * hh) * M_.diagonal().maxCoeff();  // balances the support rows
    const Vec qm = 0.5 * (q_ + q1_), vm = (q1_ - q_) / hh;
    Springs sp = frame_energy(f_, qm, 0.5);
    L_.add_hessian(qm, 0.5 * factor, sp.hess);
    support_triplets(f_, N, scale, sp.hess);
    res_.resize(N + R);
    res_.head(N) = (2.0 / (hh * hh)) * (M_ * (q1_ - q_ - hh * v_)) + sp.grad + factor * L_.gradient(qm) +
                   f_.S.transpose() * (mu1_ * scale);
    if (damped_) res_.head(N) += C_ * vm;
    res_.tail(R) = scale * (f_.S * (q1_ - f_.rest));
    Sparse A(N + R, N + R);
    A.setFromTriplets(sp.hess.begin(), sp.hess.end());
    Sparse Mt = (2.0 / (hh * hh)) * M_;
    if (damped_) Mt += C_ / hh;
    Mt.conservativeResize(N + R, N + R);
    A += Mt;
    // Solved at once (full Newton): the LU lives only here, as the memory estimate counts it.
    LU lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success || !res_.allFinite()) return false;
    d_ = lu.solve(-res_);
    return true;
  }
  bool solve(paths::Correction& c) override {
    const int N = 3 * f_.n;
    if (!d_.allFinite()) return false;
    c.size = correction_size(f_, d_.head(N), radius_);
    c.move = frame_move(f_, d_.head(N));
    return true;
  }
  void apply() override {
    const int N = 3 * f_.n;
    q1_ += d_.head(N);
    mu1_ += d_.tail(d_.size() - N);
  }

  double potential(const Vec& q) const override { return L_.potential(q); }
  double strain(const Vec& q) const override { return frame_energy(f_, q, 0.0).energy; }
  double constraint_residual(const Vec& q) const override {
    return f_.S.rows() > 0 ? (f_.S * (q - f_.rest)).cwiseAbs().maxCoeff() : 0.0;
  }
  void record(const Vec& q, paths::Sample& out) const override {
    for (int k : rec_) {
      out.ux.push_back(q[3 * k] - f_.rest[3 * k]);
      out.uy.push_back(q[3 * k + 1] - f_.rest[3 * k + 1]);
    }
  }

  const Frame& f_;
  const double radius_;
  const FrameLoads& L_;
  const std::vector<int> rec_;
  Vec res_, d_;    ///< the residual and the correction
};

}  // namespace

ring::TimeHistory frame_respond(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                const ring::ResponseOptions& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const Frame f = make_frame(spec, options);
  const FrameLoads loads(f, spec, r.loads, "response");
  const auto rec = record_nodes(f, r.record, "response.record");
  const int N = 3 * f.n;
  // Rayleigh damping C = a M + b K0, K0 the Hessian of the elements and terms at rest (the
  // linear frame's stiffness).
  FrameStepper stepper(f, r, spec.radius, loads, detail::rayleigh_damping(r, f.M, [&] { return frame_energy(f, f.rest, 1.0).hess; }),
                       rec);
  ring::TimeHistory h = detail::integrate_midpoint(stepper, spec, f.n, r,
                                                   "lumped response (" + ring::to_string(options.variant) + ")",
                                                   N + static_cast<int>(f.S.rows()));
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

}  // namespace lumped
