// The nonlinear chain's model (nonlinear.hpp: hinge positions x, rigid links, support rows,
// hinge springs, the spec's terms, the loads), written once and shared by every analysis of
// the chain: statics and response (nonlinear.cpp) and linear buckling (buckling.cpp). An
// internal header of lumped_mass/: the driver and the other solvers never include it.
//
// Unknowns x = (x_0, y_0, ..., x_{n-1}, y_{n-1}) (2n values), constraint rows g(x) = (links
// c_j, j = 0..n-1, then the support rows S (x - rest)), multipliers lambda in that order.
// Cost: O(n) time and memory for every function here.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "lumped_mass/loads.hpp"
#include "lumped_mass/terms.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The chain's fixed data: geometry, stiffness, mass, supports and the spec's terms.
struct Chain {
  int n = 0;
  double l = 0.0, k = 0.0, m = 0.0, rho = 0.0, theta0 = 0.0, anchor_deg = 0.0, depth = 0.0;
  Eigen::VectorXd rest;     ///< 2n: hinge rest positions
  /// Support rows on the hinge displacements, model.cpp's S (pins, further pins, roller):
  /// S (x - rest) = 0, linear in x.
  Eigen::SparseMatrix<double> S;
  std::optional<Terms> terms;  ///< springs, the clamp, the foundation, point masses (terms.hpp)
  /// Constraint rows: the n links, then the supports.
  int rows() const { return n + static_cast<int>(S.rows()); }

  Eigen::Vector2d at(const Eigen::VectorXd& x, int j) const {
    j = ((j % n) + n) % n;
    return {x[2 * j], x[2 * j + 1]};
  }
  /// Hinge index of a point named by its polar angle (a node, checked by the caller).
  int hinge(double deg) const {
    const double step = 360.0 / n;
    return static_cast<int>(std::lround(ring::wrap_degrees(deg - anchor_deg) / step)) % n;
  }
};

/// The chain of `spec` with n = o.n (the caller has run the checks of checks.hpp).
Chain make_chain(const ring::RingSpec& spec, const ring::LumpedOptions& o);

/// Turning angle at hinge j and its gradient with respect to (x_{j-1}, x_j, x_{j+1}).
struct Turn {
  double theta = 0.0;
  Eigen::Matrix<double, 6, 1> grad;
  Eigen::Matrix<double, 6, 6> hess;
};
Turn turn(const Chain& c, const Eigen::VectorXd& x, int j, bool with_hessian);

/// Global DoF of local index i (0..5) of the three hinges around j.
int dof(const Chain& c, int j, int i);

/// The elastic energy V, its gradient and (scaled) Hessian.
struct Springs {
  double energy = 0.0;
  Eigen::VectorXd grad;
  Triplets hess;
};
/// V, grad V and (scaled by `hess_scale`, if not zero) Hess V: the hinge springs and the
/// spec's stiffness terms (terms.hpp: springs, the clamp, the foundation).
Springs springs(const Chain& c, const Eigen::VectorXd& x, double hess_scale);

/// The tangent stiffness of the chain's equilibrium grad V(x) + G(x)^T lambda + s grad P(x)
/// on the hinge positions, times `scale`:
///   scale (Hess V(x) + sum_j lambda_j Hess c_j + s Hess P(x)),
/// with V, grad V (unscaled) as springs() gives them; `tangent.hess` holds the sum as
/// triplets of the 2n x 2n block (springs and terms, then the links, then the load
/// stiffness). Every analysis of the chain takes its tangent from here.
Springs tangent(const Chain& c, const ChainLoads& loads, const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                double s, double scale);

/// Constraint values: links (|d|^2 - l^2) / (2 l), then the supports (m).
Eigen::VectorXd constraints(const Chain& c, const Eigen::VectorXd& x);

/// The constraint Jacobian G(x) as triplets at (row_offset + row, column), times `scale`
/// (transposed: at (column, row_offset + row)).
void jacobian(const Chain& c, const Eigen::VectorXd& x, int row_offset, double scale, bool transpose, Triplets& out);

/// sum_j lambda_j Hess c_j, times `scale`: the link rows have the constant Hessian
/// (1/l)[I -I; -I I]; the support rows none.
void constraint_hessian(const Chain& c, const Eigen::VectorXd& lambda, double scale, Triplets& out);

/// The constant translational mass matrix: the midpoint masses, m/4 [I I; I I] on every
/// link, and the point masses on their hinges (terms.hpp).
Eigen::SparseMatrix<double> mass_matrix(const Chain& c);

/// The hinge of every point load (`section`.at for one load, `section`.loads[i].at for
/// several, as the scene names them). A load at the pin is refused: the pin takes it whole.
std::vector<int> load_hinges(const Chain& c, const ring::RingSpec& spec, const ring::Loads& loads,
                             const std::string& section);

}  // namespace lumped
