#include "compare/grid.hpp"

#include <algorithm>
#include <sstream>

namespace cmp {

std::string text_grid(const Cells& c) {
  if (c.empty()) return "";
  std::vector<std::size_t> w(c[0].size(), 0);
  for (const auto& r : c)
    for (std::size_t k = 0; k < r.size() && k < w.size(); ++k) w[k] = std::max(w[k], r[k].size());
  std::ostringstream s;
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t k = 0; k < c[i].size() && k < w.size(); ++k)
      s << (k ? "  " : "") << std::string(w[k] - c[i][k].size(), ' ') << c[i][k];
    s << "\n";
    if (i == 0) {
      std::size_t total = 0;
      for (std::size_t k = 0; k < w.size(); ++k) total += w[k] + (k ? 2 : 0);
      s << std::string(total, '-') << "\n";
    }
  }
  return s.str();
}

std::string markdown_grid(const Cells& c, std::size_t left) {
  std::ostringstream s;
  for (std::size_t i = 0; i < c.size(); ++i) {
    s << "|";
    for (const auto& x : c[i]) s << " " << x << " |";
    s << "\n";
    if (i == 0) {
      s << "|";
      for (std::size_t k = 0; k < c[0].size(); ++k) s << (k < left ? "---|" : "---:|");
      s << "\n";
    }
  }
  return s.str();
}

}  // namespace cmp
