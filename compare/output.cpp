#include "compare/output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>

#include "ring/errors.hpp"

namespace cmp {

void write_file(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp-" + std::to_string(getpid());
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp + ": " + std::strerror(errno));
    f << content;
    f.flush();
    if (!f) throw std::runtime_error("cannot write " + tmp + ": " + std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + std::strerror(errno));
  }
}

void make_dirs(const std::string& dir) {
  std::string partial;
  std::size_t pos = 0;
  while (pos != std::string::npos) {
    pos = dir.find('/', pos + 1);
    partial = dir.substr(0, pos);
    if (partial.empty()) continue;
    if (mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST)
      throw ring::InputError("", "--out " + dir, std::string("cannot create the folder: ") + std::strerror(errno));
  }
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw ring::InputError("", "--out " + dir, "exists and is not a folder");
}

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
