// The loads of the nonlinear chain (ring/spec.hpp `Loads`), each written ONCE as a
// potential of the hinge positions x (2n values, nonlinear.hpp's unknowns) with its
// gradient and Hessian (the load stiffness), used by the statics (residual and Newton
// tangent) and by the response (the force at the step's midpoint and the work). Every load
// here is conservative on the closed chain, so the work from rest to x at a constant load
// factor s is -s (P(x) - P(rest)), P the potential at load factor 1.
//
// The chain's masses sit at the link midpoints (nonlinear.hpp), so the distributed loads
// are discretized by the same midpoint rule over the links: link j (hinge j to j+1, rest
// length l, deformed vector d_j = x_{j+1} - x_j, midpoint y_j = (x_j + x_{j+1}) / 2):
//  - point load F at hinge h (dead): P = -F . (x_h - X_h);
//  - follower pressure: p |d_j| n_j on link j (n_j the inward normal of the deformed link,
//    J d_j / |d_j| with J the rotation by +90 deg on the counter-clockwise chain), half to
//    each end. Exactly the force of the potential P = p (A(x) - A(X)), A = 1/2 sum x_j x x_{j+1}
//    the area the chain encloses; its Hessian p Hess A is constant and symmetric;
//  - dead pressure: p l nu_j on link j, nu_j the inward normal of the rest link, half to each
//    end: P = -p l sum_j nu_j . (y_j - Y_j), linear;
//  - central pressure: p l toward the centre from the deformed link's midpoint, -p l y_j/|y_j|,
//    half to each end: P = p l sum_j (|y_j| - |Y_j|), Hessian p l/4 (I - yhat yhat^T)/|y_j| on
//    the link's two hinges;
//  - gravity g: the weight of every mass, M_t g, M_t the translational mass matrix (the links'
//    midpoint masses rho A l, half to each end, and the point masses on their hinges):
//    P = -(M_t G) . (x - X), G = (g_x, g_y, g_x, g_y, ...);
//  - the spin's centrifugal body force (set_spin, spin.hpp: a ring turning at Omega, seen from
//    the frame that turns with it): the same masses flung outward,
//    P = -Omega^2 / 2 (x^T M_t x - X^T M_t X), gradient -Omega^2 M_t x, Hessian -Omega^2 M_t
//    (the centrifugal softening; with the load factor s, s Omega^2 is the squared speed).
// On the rest n-gon the three pressures are the same force p l (nu_{j-1} + nu_j) / 2 at
// hinge j, as ring/spec.hpp asks; they differ in their load stiffness. On the regular n-gon
// this is an inward force p l cos(pi/n) at every hinge, which links under the compression
// p rho cos(pi/n) (rho the circumradius) balance exactly: uniform pressure does not move the
// inextensible chain (below its buckling pressure).
//
// Cost: O(n) for every member.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "lumped_mass/terms.hpp"
#include "ring/spec.hpp"

namespace lumped {

class ChainLoads {
 public:
  /// \param rest hinge rest positions (2n), counter-clockwise
  /// \param translational_mass the constant mass on the hinge positions (2n x 2n), for gravity
  /// \param hinges the hinge of each of loads.points (checked by the caller)
  /// \param open an arch (ring.arc): the n nodes' n - 1 links, no closing link. Point loads,
  ///        gravity and the dead and central pressures act on its links as above; the follower
  ///        pressure's potential p A keeps the closed polygon's area (the chord from the last
  ///        node to the first closing it), which is the area between the chain and its chord:
  ///        with both ends pinned the chord is fixed, the forces on the links are the follower
  ///        pressure's and the chord's act on the pinned ends (reactions). checks.hpp refuses
  ///        it on an arch with a free or unpinned end (no potential there: the follower load
  ///        on an open chain with a moving end is not conservative).
  ChainLoads(const ring::Loads& loads, const Eigen::VectorXd& rest, double side,
             const Eigen::SparseMatrix<double>& translational_mass, const std::vector<int>& hinges, bool open = false);

  /// P(x) - P(rest) at load factor 1, J.
  double potential(const Eigen::VectorXd& x) const;
  /// grad P at x (the loads' force is its negative), at load factor 1.
  Eigen::VectorXd gradient(const Eigen::VectorXd& x) const;
  /// out += scale * Hess P at x (the load stiffness: follower and central pressure only).
  void add_hessian(const Eigen::VectorXd& x, double scale, Triplets& out) const;
  bool has_stiffness() const;
  /// Adds the centrifugal body force of a spin at `speed` rad/s (file comment) on the
  /// translational mass M_t (2n x 2n, as the constructor's; kept only here, so that the other
  /// analyses carry no copy). O(n).
  void set_spin(double speed, const Eigen::SparseMatrix<double>& translational_mass) {
    spin2_ = speed * speed;
    mass_ = translational_mass;
  }

 private:
  int n_ = 0, links_ = 0;
  double l_ = 0.0;
  ring::Pressure pressure_;
  Eigen::VectorXd rest_;
  Eigen::VectorXd dead_;  ///< the position-independent force at load factor 1 (points, gravity, dead pressure)
  double area0_ = 0.0, central0_ = 0.0;
  Eigen::SparseMatrix<double> mass_;  ///< M_t of set_spin (empty without a spin)
  double spin2_ = 0.0;                ///< Omega^2 of set_spin, 1/s^2; 0: no spin
};

}  // namespace lumped
