// The option schema of a scene section: each key declared once with its type, unit,
// default, valid range or choices and help text, as deal.II's ParameterHandler declares an
// entry (declare_entry(name, default, Patterns::Integer(4), "help")). The scene reader
// checks a section against it (ring/scene.hpp), the solver fills its option struct from the
// values it read, and `ringvib keys` prints the scene reference from it (docs/scenes.md), so
// a key's default, range and documentation are written in one place: its solver's schema.
//
// Usage (a solver's folder, e.g. multibody/options.cpp):
//   ring::OptionSchema s("multibody", "the rigid-segment chain (multibody/)");
//   s.declare_integer("n", 40, 4, 100000000, "segments; every support and load point must be a hinge");
//   s.declare_choice("method", "auto", {"auto", "dense", "sparse"}, "the O(n^3) or the O(n) path");
//   ...
//   ring::MultibodyOptions o;
//   o.n = static_cast<int>(values.integer("n"));   // values: what the reader read, defaults filled
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ring/spec.hpp"

namespace ring {

/// One value of a section: an integer, a number, a boolean or a string (a choice, a theory).
using OptionValue = std::variant<long long, double, bool, std::string>;

/// One key of a section, with everything the reader checks and the reference prints.
struct OptionEntry {
  /// integer: a TOML integer in [int_min, int_max]; number: a TOML number (an integer is
  /// taken too) in [min, max] or (min, max]; boolean; choice: one of `choices`; theory: a
  /// beam theory ("euler-bernoulli" | "timoshenko") with no default of its own: absent, the
  /// model follows ring.theory, and "timoshenko" needs the ring's shear coefficient (the
  /// reader checks that, naming the key).
  enum class Type { integer, number, boolean, choice, theory };

  std::string key;  ///< within the section ("n"; the reference shows "multibody.n")
  Type type = Type::number;
  std::string unit;                        ///< SI unit for the reference ("s", "m"), "" for none
  std::optional<OptionValue> value;        ///< the default (none only for a theory)
  long long int_min = 0, int_max = 0;      ///< an integer's valid range, inclusive
  double min = -HUGE_VAL, max = HUGE_VAL;  ///< a number's valid range; max inclusive
  bool min_open = false;                   ///< a number must be > min (not >= min)
  std::vector<std::string> choices;        ///< a choice's (or theory's) valid strings
  std::string help;                        ///< the reference's "meaning" column (Markdown)
  /// The default as the reference prints it when it is no value ("`ring.theory`"); "": the
  /// value itself.
  std::string default_doc;
  /// Extra words after the generated valid range in the reference ("and a node at the roller").
  std::string valid_doc;
};

/// The keys of one section, in the order the reader reads them and the reference lists them.
class OptionSchema {
 public:
  OptionSchema() = default;
  /// `section` is the TOML section ("multibody"); `about` one line for the reference.
  OptionSchema(std::string section, std::string about) : section_(std::move(section)), about_(std::move(about)) {}

  /// Each declare_* adds a key (a second declaration of a key is a std::logic_error) and
  /// returns its entry, for the unit or notes: s.declare_number(...).unit = "s".
  OptionEntry& declare_integer(const std::string& key, long long def, long long lo, long long hi,
                               const std::string& help);
  OptionEntry& declare_number(const std::string& key, double def, double lo, double hi, const std::string& help,
                              bool lo_open = false);
  OptionEntry& declare_boolean(const std::string& key, bool def, const std::string& help);
  OptionEntry& declare_choice(const std::string& key, const std::string& def, const std::vector<std::string>& choices,
                              const std::string& help);
  OptionEntry& declare_theory(const std::string& key, const std::string& help);

  const std::string& section() const { return section_; }
  const std::string& about() const { return about_; }
  const std::vector<OptionEntry>& entries() const { return entries_; }
  std::vector<std::string> keys() const;
  const OptionEntry* find(const std::string& key) const;

 private:
  std::string section_, about_;
  std::vector<OptionEntry> entries_;
};

/// What the reader read of one section: every key of its schema, given or defaulted (a
/// theory only when given). The accessors throw std::logic_error for a key the schema does
/// not declare as that type: a solver asking for a key it did not declare is a bug.
class OptionValues {
 public:
  void set(const std::string& key, OptionValue v) { values_[key] = std::move(v); }
  /// True when the key has a value (a theory: when the scene gives it).
  bool has(const std::string& key) const { return values_.count(key) > 0; }
  long long integer(const std::string& key) const;
  double number(const std::string& key) const;
  bool boolean(const std::string& key) const;
  const std::string& choice(const std::string& key) const;
  /// A theory key's value; empty when the scene leaves it out (the model follows ring.theory).
  std::optional<Theory> theory(const std::string& key) const;

 private:
  std::map<std::string, OptionValue> values_;
};

/// Every key of `schema` at its default: what the reader fills for an absent section.
OptionValues defaults(const OptionSchema& schema);

/// The schema's keys as a Markdown table (key, unit, default, valid, meaning), under a
/// heading "### `[section]`" and the schema's `about` line: the scene reference's section.
std::string markdown(const OptionSchema& schema);

}  // namespace ring
