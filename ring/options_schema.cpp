#include "ring/options_schema.hpp"

#include <charconv>
#include <stdexcept>

namespace ring {
namespace {

/// A number as the reference prints it: the shortest digits that read back (1e-9, 0.8,
/// 600), exponents without a sign or leading zeros beyond what is needed.
std::string number_text(double x) {
  if (x == HUGE_VAL) return "inf";
  if (x == -HUGE_VAL) return "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  std::string t(buf, r.ptr);
  const auto e = t.find('e');
  if (e != std::string::npos) {
    std::string mant = t.substr(0, e), exp = t.substr(e + 1);
    const bool neg = !exp.empty() && exp[0] == '-';
    if (!exp.empty() && (exp[0] == '-' || exp[0] == '+')) exp.erase(0, 1);
    while (exp.size() > 1 && exp[0] == '0') exp.erase(0, 1);
    t = mant + "e" + (neg ? "-" : "") + exp;
  }
  return t;
}

std::string quoted_list(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& c : v) s += (s.empty() ? "" : ", ") + ("`\"" + c + "\"`");
  return s;
}

/// Markdown table cells keep their pipes as text.
std::string cell(const std::string& s) {
  std::string o;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '|' && (i == 0 || s[i - 1] != '\\')) o += '\\';
    o += s[i];
  }
  return o;
}

std::string default_text(const OptionEntry& e) {
  if (!e.default_doc.empty()) return e.default_doc;
  if (!e.value) return "none";
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, long long>)
          return std::to_string(v);
        else if constexpr (std::is_same_v<T, double>)
          return number_text(v);
        else if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else
          return "`\"" + v + "\"`";
      },
      *e.value);
}

/// The valid values in the words of the reader's messages (toml_reader.hpp): ">= 4",
/// "[2, 16]", "(0, 1000000]".
std::string valid_text(const OptionEntry& e) {
  std::string v;
  switch (e.type) {
    case OptionEntry::Type::integer:
      v = e.int_max >= 10000000 ? ">= " + std::to_string(e.int_min)
                                : "[" + std::to_string(e.int_min) + ", " + std::to_string(e.int_max) + "]";
      break;
    case OptionEntry::Type::number:
      if (e.max == HUGE_VAL)
        v = (e.min_open ? "> " : ">= ") + number_text(e.min);
      else
        v = std::string(e.min_open ? "(" : "[") + number_text(e.min) + ", " + number_text(e.max) + "]";
      break;
    case OptionEntry::Type::boolean: v = "`true`, `false`"; break;
    case OptionEntry::Type::choice:
    case OptionEntry::Type::theory: v = quoted_list(e.choices); break;
  }
  if (!e.valid_doc.empty()) v += " " + e.valid_doc;
  return v;
}

OptionEntry& add(std::vector<OptionEntry>& entries, const std::string& section, OptionEntry e) {
  for (const auto& o : entries)
    if (o.key == e.key) throw std::logic_error("option schema [" + section + "]: '" + e.key + "' is declared twice");
  entries.push_back(std::move(e));
  return entries.back();
}

}  // namespace

OptionEntry& OptionSchema::declare_integer(const std::string& key, long long def, long long lo, long long hi,
                                           const std::string& help) {
  OptionEntry e;
  e.key = key;
  e.type = OptionEntry::Type::integer;
  e.value = def;
  e.int_min = lo;
  e.int_max = hi;
  e.help = help;
  return add(entries_, section_, std::move(e));
}

OptionEntry& OptionSchema::declare_number(const std::string& key, double def, double lo, double hi,
                                          const std::string& help, bool lo_open) {
  OptionEntry e;
  e.key = key;
  e.type = OptionEntry::Type::number;
  e.value = def;
  e.min = lo;
  e.max = hi;
  e.min_open = lo_open;
  e.help = help;
  return add(entries_, section_, std::move(e));
}

OptionEntry& OptionSchema::declare_boolean(const std::string& key, bool def, const std::string& help) {
  OptionEntry e;
  e.key = key;
  e.type = OptionEntry::Type::boolean;
  e.value = def;
  e.help = help;
  return add(entries_, section_, std::move(e));
}

OptionEntry& OptionSchema::declare_choice(const std::string& key, const std::string& def,
                                          const std::vector<std::string>& choices, const std::string& help) {
  OptionEntry e;
  e.key = key;
  e.type = OptionEntry::Type::choice;
  e.value = def;
  e.choices = choices;
  e.help = help;
  return add(entries_, section_, std::move(e));
}

OptionEntry& OptionSchema::declare_theory(const std::string& key, const std::string& help) {
  OptionEntry e;
  e.key = key;
  e.type = OptionEntry::Type::theory;
  e.choices = {"euler-bernoulli", "timoshenko"};
  e.default_doc = "`ring.theory`";
  e.help = help;
  return add(entries_, section_, std::move(e));
}

std::vector<std::string> OptionSchema::keys() const {
  std::vector<std::string> k;
  for (const auto& e : entries_) k.push_back(e.key);
  return k;
}

const OptionEntry* OptionSchema::find(const std::string& key) const {
  for (const auto& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

namespace {

template <class T>
const T& get(const std::map<std::string, OptionValue>& values, const std::string& key, const char* type) {
  const auto it = values.find(key);
  if (it == values.end() || !std::holds_alternative<T>(it->second))
    throw std::logic_error(std::string("option values: no ") + type + " '" + key + "' (not declared so by the schema)");
  return std::get<T>(it->second);
}

}  // namespace

long long OptionValues::integer(const std::string& key) const { return get<long long>(values_, key, "integer"); }
double OptionValues::number(const std::string& key) const { return get<double>(values_, key, "number"); }
bool OptionValues::boolean(const std::string& key) const { return get<bool>(values_, key, "boolean"); }
const std::string& OptionValues::choice(const std::string& key) const {
  return get<std::string>(values_, key, "choice");
}
std::optional<Theory> OptionValues::theory(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return get<std::string>(values_, key, "theory") == "timoshenko" ? Theory::timoshenko : Theory::euler_bernoulli;
}

OptionValues defaults(const OptionSchema& schema) {
  OptionValues v;
  for (const auto& e : schema.entries())
    if (e.value) v.set(e.key, *e.value);
  return v;
}

std::string markdown(const OptionSchema& schema) {
  std::string o = "### `[" + schema.section() + "]`\n\n";
  if (!schema.about().empty()) o += schema.about() + "\n\n";
  o += "| key | unit | default | valid | meaning |\n|---|---|---|---|---|\n";
  for (const auto& e : schema.entries())
    o += "| `" + schema.section() + "." + e.key + "` |" + (e.unit.empty() ? " " : " " + e.unit + " ") + "| " +
         cell(default_text(e)) + " | " + cell(valid_text(e)) + " | " + cell(e.help) + " |\n";
  return o;
}

}  // namespace ring
