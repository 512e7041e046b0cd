#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "fem_reference/modes.hpp"
#include "ring/closed_form.hpp"

namespace {

ring::RingSpec timoshenko_ring(double depth_over_R, bool rectangle) {
  ring::RingSpec s;
  s.radius = 1.0;
  s.E = 2.1e11;
  s.rho = 7.8e3;
  s.theory = ring::Theory::timoshenko;
  s.nu = 0.3;
  if (rectangle) {
    s.section.shape = ring::Section::Shape::rectangle;
    s.section.height = depth_over_R * s.radius;
    s.section.width = 0.05;
  } else {
    s.section.shape = ring::Section::Shape::circle;
    s.section.diameter = depth_over_R * s.radius;
  }
  return s;
}

std::vector<double> closed_form_spectrum(const ring::RingSpec& s, int count) {
  std::vector<double> all;
  for (int k = 0; k <= 200; ++k) {
    const auto b = ring::closed_form::free_ring_timoshenko(s, k);
    for (int j = 0; j < 3; ++j) {
      if ((k == 0 && j == 0) || (k == 1 && j == 0)) continue;  // rigid
      all.push_back(b[j]);
      if (k > 0) all.push_back(b[j]);
    }
  }
  std::sort(all.begin(), all.end());
  all.resize(count);
  return all;
}

TEST(Explore, Free) {
  for (double d : {1e-3, 0.1, 0.3}) {
    const auto s = timoshenko_ring(d, true);
    const auto exact = closed_form_spectrum(s, 20);
    for (int p : {2, 3, 4}) {
      for (int n : {8, 16, 32, 64}) {
        ring::FemOptions o;
        o.elements = n;
        o.degree = p;
        const auto r = fem::compute_modes(s, o, 20);
        double worst = 0;
        for (int i = 0; i < 20; ++i) worst = std::max(worst, std::abs(r.omega[i] - exact[i]) / exact[i]);
        std::printf("d %g p %d n %d: mode1 err %.3e (%.6g vs %.6g) worst20 %.3e res %.2e\n", d, p, n,
                    (r.omega[0] - exact[0]) / exact[0], r.omega[0], exact[0], worst, r.max_residual);
      }
    }
  }
}

}  // namespace
