// Nonlinear statics on the O(n) path: the chain's equilibrium in hinge positions
// (natural.hpp), grad V(x) + s grad Pi(x) + G(x)^T lambda = 0, c(x) = 0, for the
// continuation driver. V: the hinge springs and the terms of attachments.hpp, Pi: the loads
// of loading.hpp, each taken on hinge positions from the one place it is written (with
// p_n = p_0 for the loads' closing hinge): every block couples a hinge with itself or its
// neighbours, inside the springs' band.

#include <array>
#include <optional>
#include <stdexcept>

#include "multibody/attachments.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/loading.hpp"
#include "multibody/natural.hpp"
#include "multibody/plates.hpp"

namespace multibody::natural {
namespace {

/// The natural model with [plates]' two no-slide rows and the centre row (plates.hpp) after the
/// further pins'.
Natural with_slides(Natural c, const Chain& chain, const detail::PlateContact* plates) {
  if (!plates) return c;
  for (int h : plates->slide_hinges()) {
    c.slides.push_back(h);
    c.slide_dir.push_back(plates->direction());
    c.slide_at.push_back(chain.hinge_rest(h));
  }
  const auto [a, b] = plates->slide_hinges();
  c.centres.push_back({a, b});
  c.centre_dir.push_back(plates->normal());
  c.centre_at.push_back(chain.hinge_rest(a) + chain.hinge_rest(b));
  return c;
}

/// Unknowns z = (x, lambda): hinge positions, then the multipliers (links, pin, roller,
/// further pins). The KKT matrix J, constraint rows and multipliers scaled by kappa = K / l^2
/// (the springs' stiffness scale), by the banded factorization (BandedKkt, O(n)); the arc's
/// border [J c; w^T ws] (c = dR/ds = (grad Pi, 0)) by block elimination with one more solve
/// per factorization, b = J^-1 c: y = a - y_s b with a = J^-1 rhs and
/// y_s = (rhs_s - w . a) / (ws - w . b). J is singular only at the limit point itself,
/// which the arc steps land on with probability zero; their Newton corrects the round-off
/// that its near-singularity brings. Under static.displacement (statics.hpp) the last further
/// pin's rows read x_h - X_h - s v, so c is -v on them (times kappa, as the rows are scaled).
class PositionStatics : public detail::StaticEquilibrium {
 public:
  PositionStatics(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads, double depth,
                  std::optional<Eigen::Vector2d> drive, const ring::StaticOptions::Plates* plates)
      : StaticEquilibrium(chain, spec, depth),
        terms_(chain, spec),
        loads_(chain, spec, loads, "static"),
        plates_(plates ? std::optional<detail::PlateContact>(std::in_place, chain, spec, *plates) : std::nullopt),
        c_(with_slides(make_natural(chain, terms_.pinned_hinges()), chain, plates_ ? &*plates_ : nullptr)),
        N_(2 * c_.n),
        S_(c_.size()),
        kappa_(c_.K / (c_.l * c_.l)),
        kkt_(c_),
        stop_(c_.radius()),
        drive_(drive) {
    if (drive_ && c_.pins.empty()) throw std::logic_error("multibody: a driven point needs its pin rows (held_spec)");
  }
  Eigen::Index size() const override { return S_; }
  Eigen::Index arc_size() const override { return N_; }

  bool linearize(const paths::State& s, const paths::Vector& w, double ws, paths::Vector& r) override {
    const Vec x = s.z.head(N_), lambda = s.z.tail(c_.rows());
    kkt_.clear();
    Vec rx = Vec::Zero(N_);
    add_stiffness(chain_, c_, terms_, x, rx, kkt_, &bending_);  // the hinges' trial law
    // The loads (loading.hpp) at p_0 .. p_n = p_0: the hinge gradient is dR/ds, kept in b_
    // until the factorization solves for J^-1 dR/ds in place.
    Eigen::Matrix2Xd p(2, c_.n + 1);
    p.leftCols(c_.n) = Eigen::Map<const Eigen::Matrix2Xd>(x.data(), 2, c_.n);
    p.col(c_.n) = p.col(0);
    std::vector<detail::Loading::Block> blocks;
    const Eigen::Matrix2Xd g = loads_.hinge_gradient(p, loads_.shape_dependent() ? &blocks : nullptr);
    b_.setZero(S_);
    for (int k = 0; k <= c_.n; ++k) b_.segment<2>(2 * (k % c_.n)) += g.col(k);
    rx += s.s * b_.head(N_);
    if (plates_) {  // the plates' penalty by hinge (plates.hpp), its rate in s into dR/ds
      plates_->by_hinge(Eigen::Map<const Eigen::Matrix2Xd>(x.data(), 2, c_.n), s.s, pf_, pB_, pr_);
      for (int k = 0; k < c_.n; ++k) {
        rx.segment<2>(2 * k) += pf_[k];
        b_.segment<2>(2 * k) += pr_[k];
        const int dofs[2] = {2 * k, 2 * k + 1};
        if (!pB_[k].isZero()) kkt_.add(dofs, Eigen::Matrix2d(pB_[k]));
      }
    }
    for (const detail::Loading::Block& b : blocks) {
      const int dofs[4] = {2 * (b.k % c_.n), 2 * (b.k % c_.n) + 1, 2 * (b.m % c_.n), 2 * (b.m % c_.n) + 1};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) kkt_.add(dofs[i], dofs[2 + j], s.s * b.h(i, j));
    }
    add_constraint_curvature(c_, lambda, 1.0, kkt_);
    add_constraint_jacobian(c_, x, N_, true, kappa_, kkt_, &lambda, &rx);
    add_constraint_jacobian(c_, x, N_, false, kappa_, kkt_, nullptr, nullptr);
    r.resize(S_);
    r << rx, gaps(x, s.s);
    if (drive_) b_.tail<2>() = -kappa_ * *drive_;  // the driven pin's rows are the last
    if (!r.allFinite() || !kkt_.factor()) return false;
    Vec scratch;
    kkt_.solve(b_, scratch);
    w_ = w;
    ws_ = ws;
    return b_.allFinite();
  }

  bool solve(paths::Vector& y) override {
    Vec a = y.head(S_);
    a.tail(c_.rows()) *= kappa_;
    a = kkt_.solve(a);
    const double ys = (y(S_) - w_.dot(a.head(N_))) / (ws_ - w_.dot(b_.head(N_)));
    y.head(S_) = a - ys * b_;
    y(S_) = ys;
    y.segment(N_, c_.rows()) *= kappa_;
    return y.allFinite();
  }

  double move(const paths::Vector& dz) const override { return turns_a_link_by(c_, dz.head(N_)) / detail::kBasin; }
  bool converged(const paths::State& s, const paths::Vector& dz, int iteration) override {
    if (iteration == 1) stop_ = NewtonStop(c_.radius());
    return stop_.converged(dz.head(N_).cwiseAbs().maxCoeff(), gaps(s.z.head(N_), s.s).cwiseAbs().maxCoeff());
  }
  Eigen::Matrix2Xd hinges(const paths::Vector& z) const override {
    return Eigen::Map<const Eigen::Matrix2Xd>(z.data(), 2, c_.n);
  }
  Eigen::VectorXd hinge_strains(const paths::Vector& z) const override { return turning_changes(c_, z.head(N_)); }
  paths::Vector rest() const override {
    paths::Vector z = paths::Vector::Zero(S_);
    z.head(N_) = natural::rest(chain_);
    return z;
  }
  std::array<double, 2> reaction(const paths::Vector& z) const override {
    if (!drive_) return {0.0, 0.0};
    return {-z(S_ - 2), -z(S_ - 1)};
  }
  std::optional<PlateState> plates(const paths::State& x) const override {
    if (!plates_) return std::nullopt;
    const Eigen::Matrix2Xd p = hinges(x.z);
    return PlateState{plates_->reaction(p, x.s), plates_->contact_lengths(p, x.s), plates_->energy(p, x.s)};
  }

 private:
  /// The constraints at x and load factor s: the driven pin's rows from its target s v.
  Vec gaps(const Vec& x, double s) const {
    Vec g = constraints(c_, x);
    if (drive_) g.tail<2>() -= s * *drive_;
    return g;
  }

  const detail::Attachments terms_;  ///< foundation, springs, clamp, further pins
  const detail::Loading loads_;      ///< point loads, pressure, gravity
  const std::optional<detail::PlateContact> plates_;  ///< [plates]
  std::vector<Eigen::Vector2d> pf_, pr_;            ///< its force and rate by hinge (scratch)
  std::vector<Eigen::Matrix2d> pB_;                 ///< its Hessian by hinge (scratch)
  const Natural c_;
  const int N_, S_;
  const double kappa_;
  BandedKkt kkt_;
  NewtonStop stop_;
  Vec b_, w_;  ///< J^-1 dR/ds (scaled unknowns) and the border row of the last factorization
  double ws_ = 0.0;
  const std::optional<Eigen::Vector2d> drive_;  ///< static.displacement.value, m
};

}  // namespace

std::unique_ptr<detail::StaticEquilibrium> static_equilibrium(const Chain& chain, const ring::RingSpec& spec,
                                                              const ring::Loads& loads, double depth,
                                                              std::optional<Eigen::Vector2d> drive,
                                                              const ring::StaticOptions::Plates* plates) {
  return std::make_unique<PositionStatics>(chain, spec, loads, depth, drive, plates);
}

}  // namespace multibody::natural
