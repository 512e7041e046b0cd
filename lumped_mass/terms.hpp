// The ring's terms beyond the bare ring (ring/spec.hpp: elastic supports, the chain's
// clamp, the Winkler foundation, point masses), each written ONCE, as a function of the
// model's displacement DOFs u (model.hpp's order) at ANY configuration: energy, gradient
// and Hessian. The linear model (model.cpp, assemble) takes each stiffness term's gradient
// at rest as a row of its factored stiffness B with D = k; the nonlinear chain
// (nonlinear.cpp) adds the energy, gradient and Hessian along its path and in every step.
//
// Each stiffness term is k/2 r(u)^2 with a "measure" r(u) of a few DOFs:
//   foundation at node h: r = r_h . u_h and t_h . u_h (r_h, t_h the radial and tangential unit
//     vectors of the undeformed node, fixed also in large displacements, as the spec says),
//     k = l k_r and l k_t (the node stands for one side l of ring);
//   spring at node h: r = ux_h, uy_h (global directions), k = kx, ky; and kr on the rotation
//     of the tangent at h (below; the chain: in series with 4 EI/l, model.hpp);
//   the chain's clamp: 4 EI/l on the rotation (kr -> infinity in the same convention); at an
//     arch's end (ring.arc) the half hinge 2 EI/l from the end link to the wall: the end
//     link's midpoint, where its rotation stands, is l/2 from the wall (hinge_stiffness()).
//   foundation at an arch's end node: l/2 of arch (the trapezoidal rule).
// Linear measures have a zero Hessian: these terms are exactly quadratic in u. The rotation of
// the tangent at node h is:
//   frames: the rotation unknown th_h (linear);
//   chain: the mean of the rotations of its two links from their rest directions (at an
//     arch's end node, which has one link, that link's rotation),
//     m_h = (dphi_{h-1} + dphi_h) / 2, dphi_j = atan2(e_j x d_j, e_j . d_j), d_j = x_{j+1} - x_j
//     the deformed link and e_j its unit rest direction. Exact for any rotation of a link below
//     pi from its rest direction (beyond, atan2 wraps: no term is defined there). At rest its
//     gradient is model.hpp's chord rotation (nu_j . du / l per link); it is the multibody
//     chain's m_h (multibody/attachments.hpp), written in positions.
// Point masses: m on (ux_h, uy_h) (a constant mass; its weight under gravity is loads.hpp's
// business through the translational mass), and the rotary inertia J: the frames put it on
// their rotation unknown. The chain's hinge rotation chi (model.hpp: the hinge spring EI/l is
// two half springs 2EI/l from each link to chi, kr from chi to the ground) carries it: the
// linear modes (model.cpp), the modes under load (preload.cpp) and the response
// (nonlinear.cpp) make chi an unknown of its own at every hinge with a point inertia and no
// clamp (hinge_rotations()), J on chi and kr on chi. Order 2, where J (4K / (4K + kr))^2 on
// the chord rotation m_h (chi condensed quasi-statically) converged at order 1 (1.43 -> 0.75 %
// at n = 160 -> 320 on scenes/thick-ring.toml with 1e-4 kg m^2; docs/measured.md, "multibody:
// terms beyond the paper's ring"). The split springs of
// such a hinge are written once, split(): with theta_h = phi_b - phi_a (the hinge spring's
// turning angle) and m_h = (phi_a + phi_b) / 2,
//   K (phi_a - chi)^2 + K (phi_b - chi)^2 = K theta_h^2 / 2 + 4K (m_h - chi)^2 / 2,
// so the hinge spring K theta_h^2 / 2 stays as it is and the measures m_h - chi (k = 4K) and
// chi (k = kr) join it; the linear modes take their gradients at rest as rows of B, the modes
// under load and the response their energy, gradient and Hessian at any state.
// The statics have no inertia: kr condensed on m_h (4K kr / (4K + kr)) is exact for them
// (the minimum of the split springs over chi; HingeRotations::condensed).
//
// Cost: O(terms) for every member, O(n) to build (the foundation has 2 per node).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "ring/spec.hpp"

namespace lumped {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// d angle(v) / dv = J v / |v|^2 (J: rotation by +90 deg) and its Hessian, symmetric.
Eigen::Vector2d angle_gradient(const Eigen::Vector2d& v);
Eigen::Matrix2d angle_hessian(const Eigen::Vector2d& v);

/// The node at `deg` (anchor + 360 k / n), or std::invalid_argument naming `key`.
int node_of(double deg, double anchor, int n, const std::string& key);
/// The node at `deg` of a model of `pieces` equal pieces of the spec's ring or arch: on a ring
/// node_of(deg, spec.anchor(), pieces, key); on an arch (ring.arc) ring::node_index, node k at
/// from + span k / pieces, k = 0..pieces. Else std::invalid_argument naming `key`. O(1).
int node_at(const ring::RingSpec& spec, double deg, int pieces, const std::string& key);
/// std::invalid_argument naming `key` unless v is finite and >= 0.
void check_nonnegative(double v, const std::string& key);

/// ring.variations (RingSpec::variations) in the bare ring, written ONCE here for every
/// variant of the linear model (model.cpp) and the chain's hinge springs of these terms:
/// the section and density at a polar angle, the model's pieces from them.
struct Section {
  double EA = 0.0, EI = 0.0, rhoA = 0.0, rhoI = 0.0, kGA = 0.0;
};
/// The local section at `deg` (RingSpec::EA_at...; a uniform ring: its constant values). O(harmonics).
Section section_at(const ring::RingSpec& spec, double deg);
/// The mass of the piece of ring from polar angle from_deg to to_deg (to > from, counter-clockwise)
/// that a model piece of length `length` stands for: length times the mean of rho A over the arc, the
/// mean by 3-point Gauss-Legendre in the angle (exact for polynomials of degree 5; its error
/// O(l^6) per piece, far below every model's O(l^2)); a uniform ring: rho A length exactly. O(harmonics).
double piece_mass(const ring::RingSpec& spec, double from_deg, double to_deg, double length);
/// The chain's hinge spring at the hinge at polar angle `deg`: EI(deg) / l, the local EI at the
/// hinge, the midpoint rule for the compliance integral of ds / EI over the arc of length l the
/// hinge stands for (from its link midpoint to the next): O(l^2) per hinge, the chain's order
/// (tests/lumped_mass/test_variations.cpp measures order 2). O(harmonics).
double hinge_spring(const ring::RingSpec& spec, double deg, double side);

/// A scalar function r(u) of a few DOFs at one configuration: value, gradient, Hessian.
struct Measure {
  double value = 0.0;
  std::vector<int> dofs;   ///< the DOFs r depends on
  Eigen::VectorXd grad;    ///< dr / du[dofs]
  Eigen::MatrixXd hess;    ///< d2r / du[dofs]^2; empty for a linear measure
};

/// k/2 r^2 of a measure r, added where the pointers are not null: energy; grad[dofs] += k r dr;
/// out += hess_scale k (dr dr^T + r Hess r) as triplets (when hess_scale != 0). O(dofs^2).
void add_spring(const Measure& r, double k, double* energy, Eigen::VectorXd* grad, double hess_scale, Triplets* out);

/// How the kr of a hinge of Terms::hinge_rotations() enters the energy of the positions:
/// condensed on the chord rotation m_h (4K kr / (4K + kr), the statics), or not at all (the
/// caller carries that hinge's chi and its split springs, Terms::split).
enum class HingeRotations { condensed, unknowns };

class Terms {
 public:
  /// \param rest node rest positions (x_0, y_0, x_1, ...), 2n values, on the model's n-gon
  ///        (an arch, ring.arc: its n + 1 nodes from `from` to `to`, the chain only)
  /// \param dofs_per_node 2 (chain) or 3 (frames)
  /// Throws std::invalid_argument naming the key for points off the nodes and negative or
  /// non-finite stiffnesses, masses and inertias.
  Terms(const ring::RingSpec& spec, int dofs_per_node, double anchor_deg, double side, const Eigen::VectorXd& rest);

  /// A point mass, merged by node.
  struct Inertia {
    int node = 0;
    double mass = 0.0;    ///< kg, on (ux, uy)
    double rotary = 0.0;  ///< kg m^2, on the frames' rotation(node); 0 in the chain, whose J
                          ///< rides on the hinge's own rotation (hinge_rotations())
  };
  const std::vector<Inertia>& inertia() const { return inertia_; }

  /// A chain's hinge whose rotation chi is an unknown of every analysis with inertia (file comment): a
  /// point inertia at an unclamped hinge. Half springs 2K from each link to chi, kr (finite,
  /// >= 0) from chi to the ground, J on chi.
  struct HingeRotation {
    int node = 0;
    double kr = 0.0;       ///< N m/rad
    double inertia = 0.0;  ///< J, kg m^2 (> 0)
  };
  /// Empty for the frames (their rotation unknown carries J). Ascending nodes. O(1).
  const std::vector<HingeRotation>& hinge_rotations() const { return hinge_rotations_; }
  /// Whether node h is one of hinge_rotations(). O(terms).
  bool own_rotation(int h) const;
  bool any_stiffness() const { return !springs_.empty(); }
  /// The chain's two half hinge springs at node h in parallel, the stiffness from the
  /// tangent's rotation to the hinge's own rotation chi: 4 EI/l, and 2 EI/l at an arch's end
  /// node, which has one link (the half hinge from the end link to the wall or chi). O(1).
  /// ring.variations: K = hinge_spring() at the node's angle.
  double hinge_stiffness(int h) const { return open_ && (h == 0 || h == n_ - 1) ? 0.5 * k4_[h] : k4_[h]; }

  /// The rotation of the centroid line's tangent at node h at displacement u (see above).
  Measure rotation(const Eigen::VectorXd& u, int h, bool with_hessian) const;

  /// Elastic energy of the terms at u, J. `hinges`: the kr of a hinge of hinge_rotations()
  /// condensed on m_h, or left out (the caller adds split()).
  double energy(const Eigen::VectorXd& u, HingeRotations hinges = HingeRotations::condensed) const;
  /// grad += its gradient at u.
  void add_gradient(const Eigen::VectorXd& u, Eigen::VectorXd& grad,
                    HingeRotations hinges = HingeRotations::condensed) const;
  /// out += scale * its Hessian at u, as (row, col) triplets of the DOFs.
  void add_hessian(const Eigen::VectorXd& u, double scale, Triplets& out,
                   HingeRotations hinges = HingeRotations::condensed) const;

  /// The split springs of hinge_rotations()[i] (file comment) at displacement u and rotation
  /// chi, as stiffness measures on (u, chi), chi the caller's unknown `chi_dof`: r = m_h(u) - chi
  /// with k = 4K (K = EI/l), then r = chi with k = kr when kr > 0. Their energy
  /// 2K (m_h - chi)^2 + kr chi^2 / 2 is quadratic in chi, its minimum over chi the condensed
  /// 4K kr / (4K + kr) m_h^2 / 2 (chi = 4K m_h / (4K + kr)). The chain only. O(1).
  struct Split {
    Measure r;
    double k = 0.0;
  };
  std::vector<Split> split(const Eigen::VectorXd& u, std::size_t i, double chi, int chi_dof, bool with_hessian) const;
  /// The factored stiffness at rest: one row per term, its measure's gradient at u = 0, at
  /// rows row0, row0 + 1, ...; d gets the stiffnesses (all > 0). Returns the rows added.
  /// The condensed kr at a hinge of hinge_rotations() is left out: the linear modes put kr on
  /// that hinge's own rotation (model.cpp).
  int rest_rows(int row0, Triplets& rows, std::vector<double>& d) const;

 private:
  struct Spring {
    int node = -1;                              ///< >= 0: the rotation at this node
    std::vector<std::pair<int, double>> row;    ///< else: a linear measure
    double k = 0.0;
  };
  Measure measure(const Spring& s, const Eigen::VectorXd& u, bool with_hessian) const;
  /// rotation() at an arch's end node h: its one link's rotation from its rest direction.
  Measure end_rotation(const Eigen::VectorXd& u, int h, bool with_hessian) const;

  /// Whether a spring is one that HingeRotations::unknowns leaves out.
  bool left_out(const Spring& s, HingeRotations hinges) const;

  int n_ = 0, dpn_ = 2;
  bool open_ = false;  ///< an arch (ring.arc): nodes 0 and n_ - 1 are its ends, one link each
  std::vector<double> k4_;  ///< by node: the chain's two half hinge springs 2K in parallel, 4 EI/l
  Eigen::VectorXd rest_;
  std::vector<Spring> springs_;
  std::vector<Inertia> inertia_;
  std::vector<HingeRotation> hinge_rotations_;
};

}  // namespace lumped
