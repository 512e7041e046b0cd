#include "lumped_mass/options.hpp"

namespace lumped {

const ring::OptionSchema& option_schema() {
  static const ring::OptionSchema schema = [] {
    ring::OptionSchema s("lumped", "The lumped-mass chain and frames (`lumped_mass/`).");
    s.declare_integer("n", 40, 4, 100000000, "links or elements");
    s.declare_choice("variant", "chain", {"chain", "frame", "frame-consistent", "timoshenko-frame"},
                     "see [solvers.md](solvers.md#the-solvers); also the model's theory: `\"timoshenko-frame\"` is the "
                     "Timoshenko model (needs the shear coefficient), the others Euler-Bernoulli, on either "
                     "`ring.theory` ([solvers.md, \"Thick rings\"](solvers.md#thick-rings))");
    return s;
  }();
  return schema;
}

ring::LumpedOptions read_options(const ring::OptionValues& v) {
  ring::LumpedOptions o;
  o.n = static_cast<int>(v.integer("n"));
  const std::string& variant = v.choice("variant");
  o.variant = variant == "frame"              ? ring::LumpedOptions::Variant::frame
              : variant == "frame-consistent" ? ring::LumpedOptions::Variant::frame_consistent
              : variant == "timoshenko-frame" ? ring::LumpedOptions::Variant::timoshenko_frame
                                              : ring::LumpedOptions::Variant::chain;
  return o;
}

}  // namespace lumped
