// A typed, range-checked reader of TOML tables: the generic half of the scene reader.
// Every problem is a ring::InputError naming the file, the dotted key and, when known,
// its line, or "(from --set)" for an overridden key. Unknown keys get the nearest known
// key suggested (edit distance, or a known key that starts with the unknown one).
#pragma once

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ring/errors.hpp"

namespace ring::toml_input {

inline std::string join(const std::vector<std::string>& v, const std::string& sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

inline std::string fmt_num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

/// Reads typed, range-checked values out of a TOML table and reports every problem
/// as an InputError naming the file, the dotted key and (when known) the line.
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden)
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  [[noreturn]] void fail(const std::string& key, const toml::node* node, const std::string& what) const {
    std::string k = key;
    // An overridden key, or a key inside an overridden inline table (its source line is
    // that of the --set value, not of the file).
    bool from_set = overridden_.count(key) > 0;
    for (const auto& o : overridden_) from_set |= key.rfind(o + ".", 0) == 0;
    if (from_set) k += " (from --set)";
    else if (node && node->source().begin) k += " (line " + std::to_string(node->source().begin.line) + ")";
    throw InputError(file_, k, what);
  }

  /// Rejects keys of `t` that are not in `known`, suggesting the nearest known key.
  void known_keys(const toml::table& t, const std::string& section, const std::vector<std::string>& known) const {
    for (const auto& [k, node] : t) {
      const std::string key(k.str());
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string best;
      std::size_t bd = 99;
      for (const auto& c : known) {
        const std::size_t d = edit_distance(key, c);
        if (d < bd) { bd = d; best = c; }
      }
      std::string what = "unknown key";
      for (const auto& c : known)  // a truncated key ("rotary" for "rotary_inertia")
        if (bd > 2 && key.size() >= 3 && c.rfind(key, 0) == 0) { best = c; bd = 0; }
      if (bd <= std::max<std::size_t>(2, key.size() / 3)) what += "; did you mean '" + best + "'?";
      else what += "; known keys: " + join(known);
      fail(dotted(section, key), &node, what);
    }
  }

  static std::string dotted(const std::string& section, const std::string& key) {
    return section.empty() ? key : section + "." + key;
  }

  const toml::table* table(const toml::table& t, const std::string& section, const std::string& key) const {
    const toml::node* n = t.get(key);
    if (!n) return nullptr;
    if (!n->is_table()) fail(dotted(section, key), n, "expected a table");
    return n->as_table();
  }

  double number(const toml::table& t, const std::string& section, const std::string& key, double def,
                double lo, double hi, bool lo_open = false) const {
    const toml::node* n = t.get(key);
    if (!n) return def;
    double v;
    if (auto f = n->value_exact<double>()) v = *f;
    else if (auto i = n->value_exact<int64_t>()) v = static_cast<double>(*i);
    else fail(dotted(section, key), n, "expected a number, got " + type_name(*n));
    check_range(dotted(section, key), n, v, lo, hi, lo_open);
    return v;
  }

  void check_range(const std::string& key, const toml::node* n, double v, double lo, double hi, bool lo_open) const {
    const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi;
    if (ok) return;
    std::string range;
    if (hi == HUGE_VAL) range = (lo_open ? "> " : ">= ") + fmt_num(lo);
    else range = "in " + std::string(lo_open ? "(" : "[") + fmt_num(lo) + ", " + fmt_num(hi) + "]";
    fail(key, n, "expected a number " + range + ", got " + fmt_num(v));
  }

  long long integer(const toml::table& t, const std::string& section, const std::string& key, long long def,
                    long long lo, long long hi) const {
    const toml::node* n = t.get(key);
    if (!n) return def;
    auto i = n->value_exact<int64_t>();
    if (!i) fail(dotted(section, key), n, "expected an integer, got " + type_name(*n));
    if (*i < lo || *i > hi) {
      const std::string range = hi >= 10000000 && *i >= lo ? "<= " + std::to_string(hi)
                              : hi >= 10000000 ? ">= " + std::to_string(lo)
                              : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
      fail(dotted(section, key), n, "expected an integer " + range + ", got " + std::to_string(*i));
    }
    return *i;
  }

  bool boolean(const toml::table& t, const std::string& section, const std::string& key, bool def) const {
    const toml::node* n = t.get(key);
    if (!n) return def;
    auto b = n->value_exact<bool>();
    if (!b) fail(dotted(section, key), n, "expected true or false, got " + type_name(*n));
    return *b;
  }

  std::string choice(const toml::table& t, const std::string& section, const std::string& key,
                     const std::string& def, const std::vector<std::string>& options) const {
    const toml::node* n = t.get(key);
    if (!n) return def;
    auto s = n->value_exact<std::string>();
    if (!s) fail(dotted(section, key), n, "expected one of " + quoted(options) + ", got " + type_name(*n));
    check_choice(dotted(section, key), n, *s, options);
    return *s;
  }

  void check_choice(const std::string& key, const toml::node* n, const std::string& s,
                    const std::vector<std::string>& options) const {
    if (std::find(options.begin(), options.end(), s) == options.end())
      fail(key, n, "expected one of " + quoted(options) + ", got \"" + s + "\"");
  }

  std::vector<double> numbers(const toml::table& t, const std::string& section, const std::string& key,
                              std::vector<double> def, std::size_t exact_size = 0) const {
    const toml::node* n = t.get(key);
    if (!n) return def;
    const toml::array* a = n->as_array();
    if (!a) fail(dotted(section, key), n, "expected an array of numbers, got " + type_name(*n));
    std::vector<double> v;
    for (const auto& e : *a) {
      if (auto f = e.value_exact<double>()) v.push_back(*f);
      else if (auto i = e.value_exact<int64_t>()) v.push_back(static_cast<double>(*i));
      else fail(dotted(section, key), n, "expected an array of numbers, found " + type_name(e));
      if (!std::isfinite(v.back())) fail(dotted(section, key), n, "expected finite numbers");
    }
    if (exact_size && v.size() != exact_size)
      fail(dotted(section, key), n,
           "expected " + std::to_string(exact_size) + " numbers, got " + std::to_string(v.size()));
    return v;
  }

  std::vector<std::string> strings(const toml::table& t, const std::string& section, const std::string& key,
                                   const std::vector<std::string>& options) const {
    const toml::node* n = t.get(key);
    std::vector<std::string> v;
    if (!n) return v;
    const toml::array* a = n->as_array();
    if (!a) fail(dotted(section, key), n, "expected an array of strings from " + quoted(options));
    for (const auto& e : *a) {
      auto s = e.value_exact<std::string>();
      if (!s) fail(dotted(section, key), n, "expected an array of strings from " + quoted(options));
      check_choice(dotted(section, key), n, *s, options);
      if (std::find(v.begin(), v.end(), *s) != v.end()) fail(dotted(section, key), n, "\"" + *s + "\" is listed twice");
      v.push_back(*s);
    }
    return v;
  }

  /// An array of tables (`key = [{...}, ...]` or `[[key]]`), each with its dotted name
  /// ("supports.springs[2]", 1-based) for the messages of what reads it.
  std::vector<std::pair<std::string, const toml::table*>> tables(const toml::table& t, const std::string& section,
                                                                 const std::string& key) const {
    std::vector<std::pair<std::string, const toml::table*>> v;
    const toml::node* n = t.get(key);
    if (!n) return v;
    const toml::array* a = n->as_array();
    if (!a) fail(dotted(section, key), n, "expected an array of tables, got " + type_name(*n));
    for (const auto& e : *a) {
      const std::string name = dotted(section, key) + "[" + std::to_string(v.size() + 1) + "]";
      if (!e.is_table()) fail(name, &e, "expected a table, got " + type_name(e));
      v.emplace_back(name, e.as_table());
    }
    return v;
  }

  const std::string& file() const { return file_; }

 private:
  static std::string quoted(const std::vector<std::string>& options) {
    std::vector<std::string> q;
    for (const auto& o : options) q.push_back("\"" + o + "\"");
    return join(q);
  }
  static std::string type_name(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string: return "a string";
      case toml::node_type::integer: return "an integer";
      case toml::node_type::floating_point: return "a floating-point number";
      case toml::node_type::boolean: return "a boolean";
      case toml::node_type::array: return "an array";
      case toml::node_type::table: return "a table";
      default: return "a date/time";
    }
  }

  std::string file_;
  std::set<std::string> overridden_;
};

}  // namespace ring::toml_input
