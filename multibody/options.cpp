#include "multibody/options.hpp"

#include "ring/section_law.hpp"

#include "multibody/backend.hpp"

namespace multibody {

const ring::OptionSchema& option_schema() {
  static const ring::OptionSchema schema = [] {
    ring::OptionSchema s("multibody", "The paper's rigid-segment chain (`multibody/`).");
    s.declare_integer("n", 40, 4, 100000000, "segments; every support and load point must be a hinge");
    s.declare_boolean("rotary_inertia", true, "segment rotary inertia m l^2/12");
    s.declare_choice("dependent", "robust", {"robust", "paper"},
                     "dependent coordinates: a well-conditioned null-space basis, or the paper's last two angles");
    s.declare_choice("method", "auto", {"auto", "dense", "sparse"},
                     "the O(n^3) or the O(n) path of modes (auto: sparse above n = 256), statics (above 999) and "
                     "response (above 99)");
    s.declare_theory("theory",
                     "the chain's model theory ([solvers.md, \"Thick rings\"](solvers.md#thick-rings)); "
                     "`\"timoshenko\"` needs the shear coefficient; it has modes, statics, response, buckling and "
                     "modes under load on the dense path");
    return s;
  }();
  return schema;
}

ring::MultibodyOptions read_options(const ring::OptionValues& v) {
  ring::MultibodyOptions o;
  o.n = static_cast<int>(v.integer("n"));
  o.rotary_inertia = v.boolean("rotary_inertia");
  o.dependent = v.choice("dependent") == "paper" ? ring::MultibodyOptions::Dependent::paper
                                                 : ring::MultibodyOptions::Dependent::robust;
  const std::string& m = v.choice("method");
  o.method = m == "dense"    ? ring::MultibodyOptions::Method::dense
             : m == "sparse" ? ring::MultibodyOptions::Method::sparse
                             : ring::MultibodyOptions::Method::automatic;
  o.theory = v.theory("theory");
  return o;
}

// Working memory beyond the process (compare/guard.cpp adds that), fitted to the peak
// RSS measured at n = 200 ... 10^6 (docs/commands.md, "Cost guard"; tests/compare/test_memory_estimate.cpp
// holds it within [1, 1.5] of the measured peak). Measured: dense modes 49 n^2 bytes
// (LAPACK's n x n pencil and workspace); O(n) modes n (320 + 11 count) (slopes between
// n = 10^4 and 10^5 for count = 5, 23, 50, 100: 374, 582, 879, 1412 bytes per segment;
// 596 MB at 10^6, count = 23: the band factors and the ~2 count touched columns of the
// Lanczos basis, which the shapes then overwrite); nonlinear: dense
// response 42-47 n^2, dense statics 21 n^2 (50-56 n^2 since each accepted step counts the
// tangent's unstable directions: T, the kernel basis Z, Z^T T Z and the eigensolver's
// workspace; n = 800, 400), O(n) response 1.54-1.64 KB (newmark, the
// largest; 2.07-2.09 KB before the bordered band) and O(n) statics 1.15 KB per
// segment (n = 4 10^4, 10^5: the continuation driver's states, tangent and bordered
// solve, and since it takes every term, its terms and loads by hinge; 1.00-1.02 KB before). Used: those with 3-20 % to spare.
double memory_estimate(const ring::RingSpec& spec, const ring::MultibodyOptions& o, const ring::MemoryQuery& q) {
  const double n = o.n;
  const int count = q.count;
  auto banded = [&](multibody::Analysis a) { return multibody::backend(o, spec, a) == multibody::Backend::banded; };
  // Modes under load (dense): the statics' path, then T, Z, the reduced pencil and the
  // eigensolver's work; measured 92 and 81 n^2 at n = 400, 800.
  if (count > 0 && q.preload) return 100.0 * n * n;
  // The spinning ring's gyroscopic modes (spin.hpp): the spin's statics and pencil as the modes
  // under load, then the Hermitian matrix of order 2N and its eigenvectors (complex, 2 x 64 N^2
  // bytes) with LAPACK's workspace; counted, not measured: 100 n^2 + 200 N^2.
  if (count > 0 && spec.rotation.spinning())
    return 100.0 * n * n + 200.0 * (spec.theory == ring::Theory::timoshenko ? 4.0 : 1.0) * n * n;
  // The Timoshenko chain's dense matrices are (2n)^2: its shear angles double the unknowns.
  const double N = spec.theory == ring::Theory::timoshenko ? 2.0 * n : n;
  // The O(n) modes with the terms (hinge positions, multibody/position_modes.hpp): the
  // Lanczos basis of 2n rows, the band's factors, the vectors in both coordinates; slopes
  // between n = 2 10^4 and 5 10^4 (pinned, a spring and the foundation) for count = 5, 23,
  // 50: 1579, 2165, 3476 bytes per segment, n (1370 + 42 count). Used: n (1500 + 45 count).
  if (count > 0)
    return multibody::backend(o, spec, count) == multibody::Backend::banded
               ? (spec.paper_terms_only() ? n * (380.0 + 13.0 * count) : n * (1500.0 + 45.0 * count))
               : (spec.paper_terms_only() ? 52.0 : 74.0) * N * N;  // terms: +21.5 n^2 measured at n = 1500
  double bytes = 0.0;
  // Nonlinear Timoshenko chain (dense only, multibody/sections.hpp): the response's state and
  // Newton matrices are (phi, gamma), so its n^2 terms count N^2; the statics condense gamma
  // (n unknowns) and build K_c once (68 n^2). Measured (test_memory_estimate.cpp): response
  // 33.6 and 105 MB at n = 400, 800 (estimate / peak 1.25, 1.31), statics 18.8 and 43.2 MB
  // (1.11, 1.24).
  const bool shear = spec.theory == ring::Theory::timoshenko;
  if (q.response) bytes = std::max(bytes, banded(multibody::Analysis::response) ? 1850.0 * n : 50.0 * N * N);
  if (q.statics) {
    // The O(n) statics with terms or loads beyond the paper's (Attachments, Loading, their
    // hinge blocks): 1.50 KB per segment measured (n = 4 10^4, 10^5: foundation, springs,
    // central pressure, gravity), 1.15 KB without.
    const bool terms = !spec.paper_terms_only() || !q.statics->loads.points_only();
    bytes = std::max(bytes, multibody::backend(o, spec, *q.statics) == multibody::Backend::banded
                                ? (terms ? 1750.0 : 1300.0) * n
                                : (shear ? 68.0 : 60.0) * n * n);
  }
  // ring.plastic: the hinges' committed states (bending.hpp), 16 bytes each, one per hinge
  // (resultant) or SectionLaw::kFibres (fibre), and the committed strains; counted, not
  // measured (1 KB per segment for the fibre law: the O(n) statics' own size again).
  if (spec.plastic && (q.response || q.statics))
    bytes += n * (8.0 + 16.0 * (spec.plastic->law == ring::Plastic::Law::fibre ? ring::SectionLaw::kFibres : 1));
  return bytes;
}

}  // namespace multibody
