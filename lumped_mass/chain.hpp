// The nonlinear chain's model (nonlinear.hpp: hinge positions x, rigid links, support rows,
// hinge springs, the spec's terms, the loads), written once and shared by every analysis of
// the chain: statics and response (nonlinear.cpp) and linear buckling (buckling.cpp). An
// internal header of lumped_mass/: the driver and the other solvers never include it.
//
// Unknowns x = (x_0, y_0, ..., x_{n-1}, y_{n-1}) (2n values), constraint rows g(x) = (links
// c_j, j = 0..n-1, then the support rows S (x - rest)), multipliers lambda in that order.
// An arch (ring.arc, model.hpp): Chain::n counts its lumped.n + 1 nodes, the links are
// j = 0..n-2 (no closing link), the hinge springs sit at the interior nodes 1..n-2 only
// (has_spring); an end's clamp is the terms' half hinge (terms.hpp).
// Cost: O(n) time and memory for every function here.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "lumped_mass/bending.hpp"
#include "lumped_mass/loads.hpp"
#include "lumped_mass/terms.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// The elastic energy V, its gradient and (scaled) Hessian.
struct Springs {
  double energy = 0.0;
  Eigen::VectorXd grad;
  Triplets hess;
};

/// The chain's fixed data: geometry, stiffness, mass, supports and the spec's terms.
struct Chain {
  int n = 0;                ///< nodes: lumped.n on a ring, lumped.n + 1 on an arch
  bool open = false;        ///< an arch (ring.arc): node 0 at `from`, node n - 1 at `to`
  double step_deg = 0.0;    ///< the angle between neighbouring nodes, degrees
  double l = 0.0, k = 0.0, m = 0.0, rho = 0.0, theta0 = 0.0, anchor_deg = 0.0, depth = 0.0;
  Eigen::VectorXd rest;     ///< 2n: hinge rest positions
  /// Support rows on the hinge displacements, model.cpp's S (pins, further pins, roller):
  /// S (x - rest) = 0, linear in x.
  Eigen::SparseMatrix<double> S;
  std::optional<Terms> terms;  ///< springs, the clamp, the foundation, point masses (terms.hpp)
  /// The hinge springs' law on the turning angle minus its rest value (bending.hpp): k e, or
  /// ring.plastic's from the committed states (the statics commit their own copy's).
  Bending bending;
  /// static.displacement (drive()): the driven hinge, -1 without one. Its two rows are S's
  /// last, held at S (x - rest) = s `drive` (the load factor times the driven displacement):
  /// a pin whose target moves; their multipliers are minus the rig's force on the ring.
  int driven = -1;
  Eigen::Vector2d drive{0.0, 0.0};
  /// [plates] (hold_plates()): the contact law, and the nodes at plates.axis and axis + 180,
  /// whose no-slide rows e . (x - rest) = 0 (e the plates' direction) and the centre row
  /// d_0 . (u_a + u_b) = 0 are S's last three.
  std::optional<ring::PlatePair> plates;
  std::array<int, 2> plate_nodes{-1, -1};
  /// The links: n on a ring, n - 1 on an arch (link j joins node j to j + 1).
  int links() const { return open ? n - 1 : n; }
  /// Whether hinge j has a spring (bending law): every node of a ring, an arch's interior ones.
  bool has_spring(int j) const { return !open || (j > 0 && j < n - 1); }
  /// Constraint rows: the links, then the supports.
  int rows() const { return links() + static_cast<int>(S.rows()); }

  Eigen::Vector2d at(const Eigen::VectorXd& x, int j) const {
    j = ((j % n) + n) % n;
    return {x[2 * j], x[2 * j + 1]};
  }
  /// Hinge index of a point named by its polar angle (a node, checked by the caller).
  int hinge(double deg) const {
    const int k = static_cast<int>(std::lround(ring::wrap_degrees(deg - anchor_deg) / step_deg));
    return open ? k : k % n;
  }
};

/// The chain of `spec` with n = o.n (the caller has run the checks of checks.hpp).
Chain make_chain(const ring::RingSpec& spec, const ring::LumpedOptions& o);

/// `S` with two rows appended that hold the translations of the node whose x unknown is
/// `dof` (its y next to it): the driven point's rows (static.displacement), shared by the
/// chain and the frames. O(nonzeros of S).
Eigen::SparseMatrix<double> with_point_rows(const Eigen::SparseMatrix<double>& S, int dof);

/// Drives hinge `hinge` of c (static.displacement at load factor 1: `value`, m): appends its
/// rows to c.S (with_point_rows) and sets c.driven, c.drive. The caller has checked the hinge
/// (a node on no support: checks.cpp). O(n).
void drive(Chain& c, int hinge, const Eigen::Vector2d& value);

/// d g / d s, the constraint rows' change per unit load factor: -drive on the driven rows
/// (the last two), 0 elsewhere (empty-driven: all zero). rows() values.
Eigen::VectorXd constraint_rate(const Chain& c);

/// [plates] (ring/analysis.hpp) on a closed chain, the way the chain lumps the Winkler foundation
/// (terms.hpp): at every node, for the ring length l it stands for, the penalty
/// l PlatePair::energy(g_p) of each plate p, g_p at the node's deformed place on the centroid
/// line, which is the ring's point at rest (radius R, the node's polar angle) moved by the
/// node's displacement: p_j = x_j - (1 - R / rho) X_j (X_j the node's rest position on the
/// n-gon of circumradius rho > R). The n-gon's vertices lie R pi^2 / (6 n^2) outside the ring
/// (4e-4 R at n = 64), so the gap at the vertex itself would press the ring at rest; measured
/// from the ring's point, it is 0 at the two points of first contact at rest, as the law has
/// it, and the foundation's displacements are the same ones. hold_plates() appends the two
/// no-slide rows and the centre row to c.S (the caller has checked: a closed ring, no supports,
/// both points nodes). The centre row keeps the midpoint of the two points on the plates'
/// midline: the penalty holds that while the ring touches both plates (its multiplier ~0 by
/// symmetry), but a ring that springs back clear of them on unloading would be free along d_0.
/// O(n).
void hold_plates(Chain& c, const ring::RingSpec& spec, const ring::StaticOptions::Plates& plates);
/// p_j above, m. O(1).
Eigen::Vector2d plate_point(const Chain& c, const Eigen::VectorXd& x, int j);
/// The plates' penalty at hinge positions x and load factor s added to `s_out`: its energy, its
/// gradient (l k <-g_p> d_p at node j) and, scaled by hess_scale if not zero, its tangent
/// l k d_p d_p^T where in_contact(g_p). Nothing without c.plates. O(n).
void add_plates(const Chain& c, const Eigen::VectorXd& x, double s, double hess_scale, Springs& s_out);
/// d(grad of the penalty)/ds at x, s: -l k (d g_p / ds) d_p = l k (travel / 2) d_p where
/// in_contact(g_p) (the tangent's rule, so that the load column is not 0 at rest); 2n values,
/// zero without plates. The bordered system's load column. O(n).
Eigen::VectorXd plate_rate(const Chain& c, const Eigen::VectorXd& x, double s);
/// The total pressure of each plate on the ring, sum_j l k <-g_p>, N (plate 0: at plates.axis). O(n).
std::array<double, 2> plate_loads(const Chain& c, const Eigen::VectorXd& x, double s);
/// PlatePair::contact_lengths at the nodes' points p_j in order around the ring, m. O(n).
std::array<double, 2> plate_contact_lengths(const Chain& c, const Eigen::VectorXd& x, double s);

/// Turning angle at hinge j and its gradient with respect to (x_{j-1}, x_j, x_{j+1}).
struct Turn {
  double theta = 0.0;
  Eigen::Matrix<double, 6, 1> grad;
  Eigen::Matrix<double, 6, 6> hess;
};
Turn turn(const Chain& c, const Eigen::VectorXd& x, int j, bool with_hessian);

/// Global DoF of local index i (0..5) of the three hinges around j.
int dof(const Chain& c, int j, int i);

/// V, grad V and (scaled by `hess_scale`, if not zero) Hess V: the hinge springs (their
/// law c.bending's: V counts its incremental potential from the committed states) and the
/// spec's stiffness terms (terms.hpp: springs, the clamp, the foundation). q: the 2n hinge
/// positions x (statics, buckling: the kr of a hinge with a point inertia condensed on its
/// chord rotation), or x followed by the rotation chi of every Terms::hinge_rotations() entry
/// in that order (the response's and the modes under load's unknowns: that kr is then the
/// hinge's split springs on chi, Terms::split), with grad and Hess of q's size. Else
/// std::logic_error. `hinges` false leaves the hinge springs out (the response's plastic step
/// adds them as a discrete gradient itself: nonlinear.cpp, ChainStepper).
Springs springs(const Chain& c, const Eigen::VectorXd& q, double hess_scale, bool hinges = true);
/// The rotations chi of Terms::hinge_rotations() (in its order) at which their split springs
/// are in equilibrium with the positions x (2n values): their minimum over chi, the state the
/// condensed kr of the statics stands for, chi = 4K m_h / (4K + kr). O(hinges).
Eigen::VectorXd relaxed_rotations(const Chain& c, const Eigen::VectorXd& x);
/// The spec's stiffness terms at displacement u added to s (energy, gradient of the size of
/// u, and the Hessian scaled by `hess_scale` if not zero): the part of springs() and of the
/// frame's energy (frame.hpp) that the two models share. O(terms).
void add_terms(const Terms& terms, const Eigen::VectorXd& u, double hess_scale, Springs& s,
               HingeRotations hinges = HingeRotations::condensed);

/// The resultant force the ground exerts on the nodes (`dofs_per_node` unknowns each, the
/// translations first) at displacement u: the support rows' -S^T mu and the terms'
/// -grad V_terms (springs, foundation; a clamp's moment has no resultant). O(n).
std::array<double, 2> ground_force(const Eigen::SparseMatrix<double>& S, const Eigen::VectorXd& mu,
                                   const Terms& terms, const Eigen::VectorXd& u, int dofs_per_node);

/// The tangent stiffness of the chain's equilibrium grad V(x) + G(x)^T lambda + s grad P(x)
/// on the hinge positions (or on q = (x, chi), as springs() takes it), times `scale`:
///   scale (Hess V(x) + sum_j lambda_j Hess c_j + s Hess P(x)),
/// with [plates] (c.plates) the plates' penalty at load factor s in V (add_plates: energy,
/// gradient and tangent),
/// with V, grad V (unscaled) as springs() gives them; `tangent.hess` holds the sum as
/// triplets of the 2n x 2n block (springs and terms, then the links, then the load
/// stiffness). Every analysis of the chain takes its tangent from here.
Springs tangent(const Chain& c, const ChainLoads& loads, const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                double s, double scale, bool hinges = true);

/// The hinge rotations e_j = theta_j - 2 pi / n at the positions x (c.bending's strains), rad
/// (an arch: 0 at its ends, which have no spring).
std::vector<double> bending_strains(const Chain& c, const Eigen::VectorXd& x);

/// Constraint values: links (|d|^2 - l^2) / (2 l), then the supports (m); a driven point's rows
/// S (x - rest) without the target (the statics add s constraint_rate(c)).
Eigen::VectorXd constraints(const Chain& c, const Eigen::VectorXd& x);

/// The constraint Jacobian G(x) as triplets at (row_offset + row, column), times `scale`
/// (transposed: at (column, row_offset + row)).
void jacobian(const Chain& c, const Eigen::VectorXd& x, int row_offset, double scale, bool transpose, Triplets& out);

/// sum_j lambda_j Hess c_j, times `scale`: the link rows have the constant Hessian
/// (1/l)[I -I; -I I]; the support rows none.
void constraint_hessian(const Chain& c, const Eigen::VectorXd& lambda, double scale, Triplets& out);

/// The constant translational mass matrix: the midpoint masses, m/4 [I I; I I] on every
/// link (an arch's end node: one link's), and the point masses on their hinges (terms.hpp), 2n x 2n; with
/// HingeRotations::unknowns on q = (x, chi) (springs()), J on every hinge rotation chi.
Eigen::SparseMatrix<double> mass_matrix(const Chain& c, HingeRotations hinges = HingeRotations::condensed);

/// The hinge of every point load (`section`.at for one load, `section`.loads[i].at for
/// several, as the scene names them). A load at the pin is refused: the pin takes it whole.
std::vector<int> load_hinges(const Chain& c, const ring::RingSpec& spec, const ring::Loads& loads,
                             const std::string& section);

/// Smallest distance between the centre lines of links at least `gap` apart along the chain
/// (link j runs from hinge j to hinge j + 1; gap = 2 + floor(2 depth / l), so that the
/// undeformed chain is clear of the depth); links closer than the section depth mean the
/// ring touches itself. Links, not hinges: with l above the depth, two links can cross while
/// every hinge is still farther than the depth from the others (n = 40 on the paper's ring
/// under ring-collapse.toml's loads: the hinges met at load factor 0.986, the links at
/// 0.859). A uniform grid of cell l + depth over the links' midpoints: links closer than the
/// depth have midpoints in neighbouring cells, so only those pairs are measured, O(n)
/// expected; pairs not measured count as infinitely far. Reads c.n, c.l, c.depth and the 2n
/// positions x only (the frame's chords use it too, frame.cpp). Defined in nonlinear.cpp.
struct Contact {
  double distance = INFINITY;
  int i = -1, j = -1;  ///< the links
};
Contact closest_nonadjacent(const Chain& c, const Eigen::VectorXd& x);
/// Where the ring touches itself: the two links and their distance.
std::string contact_where(const Chain& c, const Contact& k);

/// Factorizes the bordered Newton matrix of a continuation step, [A, b; w^T, ws] (A given
/// as triplets of a size x size matrix, b and w of `size` values, zeros skipped), by one
/// sparse LU (COLAMD). False when the factorization fails. O(nonzeros) fill on the ring's
/// banded pattern. Shared by the chain's and the frame's statics.
bool factor_bordered(Triplets t, int size, const Eigen::VectorXd& b, const Eigen::VectorXd& w, double ws,
                     Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>& lu);

}  // namespace lumped
