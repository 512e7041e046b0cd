#include "fem_reference/options.hpp"

#include <algorithm>

#include "fem_reference/checks.hpp"

namespace fem {

const ring::OptionSchema& option_schema() {
  static const ring::OptionSchema schema = [] {
    ring::OptionSchema s("fem",
                         "The curved-beam finite elements on deal.II (`fem_reference/`), and the converged reference.");
    s.declare_integer("elements", 40, 4, 10000000,
                      "elements around the ring; with `fem.degree`, at most what double precision resolves (about "
                      "3600 elements at degree 12, 7800 at 8; more is refused, naming the limit: "
                      "[`fem_reference/README.md`](../fem_reference/README.md), \"The precision limit\")");
    s.declare_integer("degree", 3, kMinDegree, kMaxDegree,
                      "polynomial degree p (`fem::kMaxDegree`, the reference's own cap: `fem_reference/checks.hpp`)");
    s.declare_choice("geometry", "curved", {"curved", "polygon"},
                     "exact circle, or straight chords (as the paper's SAP5 run)");
    s.declare_boolean("extensible", true, "axial strain energy EA (false: the inextensible limit)");
    s.declare_boolean("rotary_inertia", false, "cross-section rotary inertia rho I");
    s.declare_boolean("reference", false, "refine until the frequencies change by less than `fem.tolerance`");
    s.declare_number("tolerance", 1e-9, 1e-14, 1e-2,
                     "relative change that ends the refinement (modes; static displacements)");
    s.declare_number("response_tolerance", 1e-3, 1e-8, 1e-1,
                     "relative change of the recorded peaks that ends the reference response's refinement (degree + "
                     "1 and dt / 2 per step)");
    s.declare_theory("theory",
                     "the FE model's theory ([solvers.md, \"Thick rings\"](solvers.md#thick-rings)); the reference "
                     "ignores it and solves `ring.theory`; `\"timoshenko\"` needs the shear coefficient");
    return s;
  }();
  return schema;
}

ring::FemOptions read_options(const ring::OptionValues& v) {
  ring::FemOptions o;
  o.elements = static_cast<int>(v.integer("elements"));
  o.degree = static_cast<int>(v.integer("degree"));
  o.geometry =
      v.choice("geometry") == "polygon" ? ring::FemOptions::Geometry::polygon : ring::FemOptions::Geometry::curved;
  o.extensible = v.boolean("extensible");
  o.rotary_inertia = v.boolean("rotary_inertia");
  o.reference = v.boolean("reference");
  o.tolerance = v.number("tolerance");
  o.response_tolerance = v.number("response_tolerance");
  o.theory = v.theory("theory");
  return o;
}

// Working memory per unknown (2 p N of them), fitted to the peak RSS measured at
// N p = 2400 ... 96 000 unknowns, p = 3 ... 12 (the deal.II plug-in itself is the
// guard's): modes, UMFPACK's factors and the eigen-solve, 4.05 KB (p = 3), 5.65 KB
// (6), 9.57 KB (12) with 23 modes, + 85 bytes per mode above ~23 (ARPACK's basis and
// the refinement's long double vectors outgrow the factorization's peak); nonlinear,
// Newton's tangent and factors, 3.5-4.5 KB (p = 3) and 6.6-7.6 KB (p = 8); 5.2 KB at p = 3
// (24 000 unknowns) since each accepted step counts the tangent's unstable directions
// (its banded block LDL^T). Used: a fit
// in p with ~4 % to spare. The reference raises p to fem::kMaxDegree (checks.hpp).
double memory_estimate(const ring::RingSpec& spec, const ring::FemOptions& o, const ring::MemoryQuery& q) {
  const int count = q.count;
  const double p = o.reference || q.reference ? fem::kMaxDegree : o.degree;
  const double unknowns = (spec.theory == ring::Theory::timoshenko ? 3.0 : 2.0) * p * o.elements;
  if (count == 0) return unknowns * (3400.0 + 650.0 * p);
  // Modes under load: the statics, then the dense pencil (three N x N matrices and the
  // eigen-solve's work, fem_reference/preload.hpp), ~100 N^2.
  if (q.preload) return unknowns * (3400.0 + 650.0 * p) + 100.0 * unknowns * unknowns;
  const double factor_peak = 2800.0 + 430.0 * p + 14.0 * p * p;
  return unknowns * (factor_peak + 85.0 * std::max(0, count - 23));
}

}  // namespace fem
