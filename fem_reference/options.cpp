#include "fem_reference/options.hpp"

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

}  // namespace fem
