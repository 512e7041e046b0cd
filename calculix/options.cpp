#include "calculix/options.hpp"

#include <algorithm>
#include "calculix/deck.hpp"

namespace calculix {

const ring::OptionSchema& option_schema() {
  static const ring::OptionSchema schema = [] {
    ring::OptionSchema s("calculix", "The external CalculiX column (`calculix/`; needs `ccx`).");
    s.declare_integer("elements", 160, 4, 1000000,
                      "beam elements around the ring (B31: as many nodes; B32, B32R: twice as many, the middle nodes "
                      "on the circle)")
        .valid_doc = "(and a node at the roller)";
    s.declare_choice("element", "B32R", {"B31", "B32R", "B32"},
                     "`B32R` quadratic with reduced integration (order 4), `B32` quadratic (shear-locks: order ~3.5, "
                     "0.1 % high at 160 elements), `B31` linear (order 2: slow)");
    s.declare_choice("section", "equivalent-rectangle", {"equivalent-rectangle", "as-given"},
                     "a RECT of the ring's A and I (width A/h, radial height h = sqrt(12 I/A)), or the scene's circle "
                     "(`CIRC`, whose expansion is 0.6 % off) or rectangle; a section given by `{area, inertia}` has no "
                     "shape: `\"as-given\"` refuses it");
    s.declare_number("timeout", 600.0, 0.0, 1e6, "the longest one ccx run may take; then it is killed (exit 3)", true)
        .unit = "s";
    s.declare_integer("threads", 1, 1, 1024, "ccx's threads (`OMP_NUM_THREADS`, `CCX_NPROC_*`)");
    return s;
  }();
  return schema;
}

ring::CalculixOptions read_options(const ring::OptionValues& v) {
  ring::CalculixOptions o;
  o.elements = static_cast<int>(v.integer("elements"));
  const std::string& e = v.choice("element");
  o.element = e == "B31"   ? ring::CalculixOptions::Element::b31
              : e == "B32" ? ring::CalculixOptions::Element::b32
                           : ring::CalculixOptions::Element::b32r;
  o.section = v.choice("section") == "as-given" ? ring::CalculixOptions::Section::as_given
                                                : ring::CalculixOptions::Section::equivalent_rectangle;
  o.timeout = v.number("timeout");
  o.threads = static_cast<int>(v.integer("threads"));
  return o;
}

// ccx runs in its own process: ringvib holds the deck and the .dat text, a few KB per
// node and mode; ccx's own memory (about 100 MB at 640 B32R elements) is not ringvib's.
double memory_estimate(const ring::CalculixOptions& o, const ring::MemoryQuery& q) {
  return calculix::node_count(o) * (2000.0 + 200.0 * std::max(q.count, 1));
}

}  // namespace calculix
