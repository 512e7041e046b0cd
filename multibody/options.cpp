#include "multibody/options.hpp"

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

}  // namespace multibody
