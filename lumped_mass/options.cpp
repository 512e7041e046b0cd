#include "lumped_mass/options.hpp"

#include <algorithm>

#include "ring/section_law.hpp"

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

// Working memory per node, fitted to the peak RSS measured at n = 10^3 ... 6 10^5: the
// sparse LU's peak, or (from ~20 modes up) the factors plus the Lanczos basis,
// 40 bytes per node and mode. Modes, with count 23: chain 4.1-4.4 KB, frame 5.8-5.9 KB,
// frame-consistent 7.8-8.3 KB per node (linear up to n = 6 10^5, 4.6 GB); the nonlinear
// chain 4.5 KB (statics) to 5.0 KB (response; 5.3-5.5 KB at n = 10^4, 3 10^4 since it
// carries the hinge rotations' state, q = (x, chi), and their mass beside the translational
// one: 172.5 MB measured at 3 10^4, where 5.2 KB had been 165.4); the corotational frames'
// statics 5.4 and 4.6 KB at n = 10^4, 3 10^4 (the process included). Used: those with 3-5 %
// to spare.
double memory_estimate(const ring::RingSpec& spec, const ring::LumpedOptions& o, const ring::MemoryQuery& q) {
  const int count = q.count;
  const double n = o.n;
  const bool frame = o.variant != ring::LumpedOptions::Variant::chain;
  // ring.plastic: the hinges' committed states (bending.hpp), 16 bytes each, one per hinge
  // (resultant law) or per fibre (SectionLaw::kFibres), and the response's copy of the chain
  // that holds them (counted, not measured).
  const double plastic =
      spec.plastic && (q.response || q.statics)
          ? n * (16.0 * (spec.plastic->law == ring::Plastic::Law::fibre ? ring::SectionLaw::kFibres : 1) +
                 (q.response ? 5700.0 : 0.0))
          : 0.0;
  if (count == 0) return (frame ? 5600.0 : 5850.0) * n + plastic;
  // Modes under load are dense (lumped_mass/preload.hpp): measured 99 and 84 n^2 at
  // n = 400, 800 (the process's 8 MB aside); the frames' 3n unknowns 567 and 523 n^2.
  if (q.preload) return (frame ? 600.0 : 100.0) * n * n;
  // A spinning ring's modes are dense too (lumped_mass/spin.hpp), counted, not measured: the
  // Hermitian eigenproblem of order 2N (its matrix, vectors and workspace, 3 x 16 (2N)^2 bytes)
  // and the real N^2, Q^2 blocks, N ~ n unknowns on the chain's kernel (~400 n^2 in all),
  // N = 3n on the frame (~2400 n^2).
  if (spec.rotation.spinning()) return (frame ? 2400.0 : 400.0) * n * n;
  auto per_node = [count](double factor_peak, double with_basis) {
    return std::max(factor_peak, with_basis + 40.0 * count);
  };
  // The factors' peaks rose by 2 to 12 % (most in the frames at n = 10^4) with a change to
  // the statics (lumped_mass/nonlinear.cpp, the plates) that the modes do not run: the same
  // allocations (heaptrack: 35374 calls, a 215.68 MB heap peak), the same frequencies, more of
  // SparseLU's reserved workspace touched. Refitted to the measured peaks at n = 10^4 and 3 10^4.
  switch (o.variant) {
    case ring::LumpedOptions::Variant::chain: return n * per_node(4500.0, 4150.0);
    case ring::LumpedOptions::Variant::frame: return n * per_node(6950.0, 4250.0);
    case ring::LumpedOptions::Variant::frame_consistent: return n * per_node(9150.0, 7600.0);
    // Measured 7.7, 7.5, 7.5 KB per node at n = 10^4, 3 10^4, 10^5 (count 23): the factors'
    // peak; the mixed system has 7n rows (4 strains per element) but a diagonal mass.
    case ring::LumpedOptions::Variant::timoshenko_frame: return n * per_node(8600.0, 7000.0);
  }
  return 0.0;
}

}  // namespace lumped
