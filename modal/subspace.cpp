#include "modal/subspace.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace modal {

int subspace_size(int nev, int n) {
  if (nev < 1 || nev > n - 1)
    throw std::invalid_argument("modal: nev = " + std::to_string(nev) + " must satisfy 1 <= nev <= n - 1 = " +
                                std::to_string(n - 1) + " (n = problem size)");
  return std::min(n, std::max(2 * nev + 1, nev + 20));
}

}  // namespace modal
