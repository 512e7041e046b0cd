#include "compare/output.hpp"

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
  int decimals = std::max(0, 3 - mag);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  // Rounding can carry into a new digit (9.9996 -> 10.000): recompute once.
  const double r = std::atof(buf);
  if (r != 0.0 && static_cast<int>(std::floor(std::log10(std::abs(r)))) != mag) {
    decimals = std::max(0, decimals - 1);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  return buf;
}

std::string model_value(const ring::ModelValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const std::string* s = std::get_if<std::string>(&v)) return *s;
  if (const long long* i = std::get_if<long long>(&v)) return std::to_string(*i);
  std::ostringstream s;
  s << std::get<double>(v);
  return s.str();
}

std::string pct2(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return std::string(buf) == "-0.00" ? "0.00" : buf;
}

}  // namespace cmp
