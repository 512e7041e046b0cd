#include "compare/output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace cmp {

std::string sig4(double v) {
  if (!std::isfinite(v)) return "nan";
  if (v == 0.0) return "0.000";
  const int mag = static_cast<int>(std::floor(std::log10(std::abs(v))));
  const int decimals = std::max(0, 3 - mag);
  std::string text = fmt::format("{:.{}f}", v, decimals);
  // Rounding can carry into a new digit (9.9996 -> 10.000): recompute once.
  const double r = std::atof(text.c_str());
  if (r != 0.0 && static_cast<int>(std::floor(std::log10(std::abs(r)))) != mag)
    text = fmt::format("{:.{}f}", v, std::max(0, decimals - 1));
  return text;
}

std::string model_value(const ring::ModelValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const std::string* s = std::get_if<std::string>(&v)) return *s;
  if (const long long* i = std::get_if<long long>(&v)) return std::to_string(*i);
  std::ostringstream s;
  s << std::get<double>(v);
  return s.str();
}

std::string residual_cell(const ring::ModalResult& m) {
  return m.max_residual ? fmt::format("{:.1e}", *m.max_residual) : "-";
}

std::string pct2(double v) {
  const std::string text = fmt::format("{:.2f}", v);
  return text == "-0.00" ? "0.00" : text;
}

}  // namespace cmp
