#include "options.hpp"

#include <charconv>
#include <climits>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "cli_common.hpp"  // UsageError

namespace exactccd::cli {
namespace {

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

/// What the table says of an option's value, for the help: range or choices, default, required.
std::string value_facts(const OptionSpec& o) {
  std::vector<std::string> facts;
  switch (o.type) {
    case ValueType::integer:
      facts.push_back(o.max == LLONG_MAX ? o.value_name + " >= " + std::to_string(o.min)
                                         : o.value_name + " in " + std::to_string(o.min) + ".." +
                                               std::to_string(o.max));
      break;
    case ValueType::unsigned64:
      facts.push_back(o.value_name + " in 0..2^64-1");
      break;
    case ValueType::real: {
      std::ostringstream range;
      range << o.value_name << " in [" << o.real_min << ", " << o.real_max << "]";
      facts.push_back(range.str());
      break;
    }
    case ValueType::choice:
      if (!o.value_name.empty() && o.value_name != join(o.choices, "|"))
        facts.push_back("one of " + join(o.choices, ", "));
      break;
    case ValueType::choice_list:
      facts.push_back("comma-separated, of " + join(o.choices, ", ") + "; or all");
      break;
    case ValueType::shard:
      facts.push_back("0 <= I < N <= " + std::to_string(o.max));
      break;
    case ValueType::flag:
    case ValueType::text:
      break;
  }
  if (!o.default_value.empty()) facts.push_back("default " + o.default_value);
  if (o.required) facts.push_back("required");
  return facts.empty() ? "" : "(" + join(facts, "; ") + ")";
}

constexpr std::size_t kHelpColumn = 22;  // where the help text of an option starts

/// `text` broken into lines of at most `width` characters at spaces (a longer word stays whole).
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string line;
  for (std::string w; words >> w;) {
    if (!line.empty() && line.size() + 1 + w.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + w;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string help_entry(const OptionSpec& o) {
  std::string head = "  " + o.name;
  if (o.type != ValueType::flag) head += " " + o.value_name;
  std::vector<std::string> lines;
  std::istringstream paragraphs(o.help);
  for (std::string l; std::getline(paragraphs, l);) lines.push_back(l);
  const std::string facts = value_facts(o);
  if (!facts.empty()) {
    constexpr std::size_t kWidth = 96 - kHelpColumn;
    // The facts continue the last line when they fit, else they are wrapped below it.
    if (!lines.empty() && lines.back().size() + 1 + facts.size() <= kWidth)
      lines.back() += " " + facts;
    else
      for (const std::string& w : wrap(facts, kWidth)) lines.push_back(w);
  }
  std::string out = head;
  if (out.size() + 1 > kHelpColumn) {
    out += "\n";
    out += std::string(kHelpColumn, ' ');
  } else {
    out += std::string(kHelpColumn - out.size(), ' ');
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) out += std::string(kHelpColumn, ' ');
    out += lines[i] + "\n";
  }
  if (lines.empty()) out += "\n";
  return out;
}

[[noreturn]] void bad_value(const CommandSpec& c, const OptionSpec& o, const std::string& needs,
                            const std::string& value) {
  throw UsageError(c.name + ": " + o.name + " needs " + needs + ", not '" + value + "'");
}

/// `v` as a decimal or hexadecimal floating-point literal ("0x1p-40", "-0x1.8p1") that it reads
/// as in full (the nearest double, as the data files' strtod), else nullopt.
std::optional<double> parse_real(const std::string& v) {
  double x = 0;
  const char* first = v.data();
  const char* last = v.data() + v.size();
  const bool negative = !v.empty() && v[0] == '-';
  const char* digits = first + (negative ? 1 : 0);
  if (last - digits > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    if (digits[2] == '-' || digits[2] == '+') return std::nullopt;  // "0x-1": not a literal
    const auto [end, error] = std::from_chars(digits + 2, last, x, std::chars_format::hex);
    if (error != std::errc() || end != last) return std::nullopt;
    return negative ? -x : x;
  }
  const auto [end, error] = std::from_chars(first, last, x);
  if (v.empty() || error != std::errc() || end != last) return std::nullopt;
  return x;
}

long long parse_integer_value(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  const auto n = parse_integer_strictly(v);
  if (!n || *n < o.min || *n > o.max)
    bad_value(c, o, o.max == LLONG_MAX ? "an integer >= " + std::to_string(o.min)
                                       : "an integer in " + std::to_string(o.min) + ".." + std::to_string(o.max),
              v);
  return *n;
}

std::uint64_t parse_unsigned64_value(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  std::uint64_t n = 0;
  const char* last = v.data() + v.size();
  const auto [end, error] = std::from_chars(v.data(), last, n);
  if (v.empty() || v[0] == '-' || error != std::errc() || end != last)
    bad_value(c, o, "an integer in 0..18446744073709551615", v);
  return n;
}

double parse_real_value(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  const std::optional<double> x = parse_real(v);
  std::ostringstream range;
  range << "a finite number in [" << o.real_min << ", " << o.real_max << "]";
  if (!x || !std::isfinite(*x) || *x < o.real_min || *x > o.real_max) bad_value(c, o, range.str(), v);
  return *x;
}

bool is_choice(const OptionSpec& o, const std::string& v) {
  bool known = false;
  for (const std::string& s : o.choices) known = known || s == v;
  return known;
}

std::vector<std::string> parse_choice_list(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  if (v == "all") return o.choices;
  const std::string needs = "a comma-separated list of " + join(o.choices, ", ") + " or all";
  std::vector<std::string> list;
  std::string item;
  std::istringstream items(v);
  while (std::getline(items, item, ',')) {
    if (!is_choice(o, item)) bad_value(c, o, needs, v);
    list.push_back(item);
  }
  if (list.empty() || v.back() == ',') bad_value(c, o, needs, v);
  return list;
}

std::pair<std::size_t, std::size_t> parse_shard(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  const auto slash = v.find('/');
  const auto index = slash == std::string::npos ? std::nullopt : parse_integer_strictly(v.substr(0, slash));
  const auto count = slash == std::string::npos ? std::nullopt : parse_integer_strictly(v.substr(slash + 1));
  if (!index || !count || *index < 0 || *count < 1 || *index >= *count || *count > o.max)
    bad_value(c, o, "I/N with 0 <= I < N <= " + std::to_string(o.max), v);
  return {static_cast<std::size_t>(*index), static_cast<std::size_t>(*count)};
}

OptionValue parse_value(const CommandSpec& c, const OptionSpec& o, const std::string& v) {
  OptionValue out;
  out.text = v;
  switch (o.type) {
    case ValueType::flag:
      break;
    case ValueType::integer:
      out.integer = parse_integer_value(c, o, v);
      break;
    case ValueType::unsigned64:
      out.unsigned64 = parse_unsigned64_value(c, o, v);
      break;
    case ValueType::real:
      out.real = parse_real_value(c, o, v);
      break;
    case ValueType::text:
      if (v.empty()) bad_value(c, o, "a non-empty value", v);
      break;
    case ValueType::choice:
      if (!is_choice(o, v)) bad_value(c, o, "one of " + join(o.choices, ", "), v);
      break;
    case ValueType::choice_list:
      out.list = parse_choice_list(c, o, v);
      break;
    case ValueType::shard:
      out.shard = parse_shard(c, o, v);
      break;
  }
  return out;
}

OptionSpec make(const std::string& name, ValueType type, const std::string& value_name,
                const std::string& default_value, const std::string& help) {
  OptionSpec o;
  o.name = name;
  o.type = type;
  o.value_name = value_name;
  o.default_value = default_value;
  o.help = help;
  return o;
}

}  // namespace

OptionSpec flag_option(const std::string& name, const std::string& help) {
  return make(name, ValueType::flag, "", "", help);
}

OptionSpec integer_option(const std::string& name, const std::string& value_name, long long min,
                          long long max, const std::string& default_value, const std::string& help) {
  OptionSpec o = make(name, ValueType::integer, value_name, default_value, help);
  o.min = min;
  o.max = max;
  return o;
}

OptionSpec unsigned64_option(const std::string& name, const std::string& value_name,
                             const std::string& default_value, const std::string& help) {
  return make(name, ValueType::unsigned64, value_name, default_value, help);
}

OptionSpec real_option(const std::string& name, const std::string& value_name, double min, double max,
                       const std::string& default_value, const std::string& help) {
  OptionSpec o = make(name, ValueType::real, value_name, default_value, help);
  o.real_min = min;
  o.real_max = max;
  return o;
}

OptionSpec text_option(const std::string& name, const std::string& value_name,
                       const std::string& default_value, const std::string& help) {
  return make(name, ValueType::text, value_name, default_value, help);
}

OptionSpec choice_option(const std::string& name, const std::string& value_name,
                         std::vector<std::string> choices, const std::string& default_value,
                         const std::string& help) {
  OptionSpec o = make(name, ValueType::choice, value_name.empty() ? join(choices, "|") : value_name,
                      default_value, help);
  o.choices = std::move(choices);
  return o;
}

OptionSpec choice_list_option(const std::string& name, const std::string& value_name,
                              std::vector<std::string> choices, const std::string& default_value,
                              const std::string& help) {
  OptionSpec o = make(name, ValueType::choice_list, value_name, default_value, help);
  o.choices = std::move(choices);
  return o;
}

OptionSpec shard_option(const std::string& name, long long max_count, const std::string& help) {
  OptionSpec o = make(name, ValueType::shard, "I/N", "", help);
  o.max = max_count;
  return o;
}

OptionSpec required(OptionSpec spec) {
  spec.required = true;
  return spec;
}

std::string help_text(const CommandSpec& command) {
  const auto trimmed = [](std::string s) {
    while (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
  };
  std::string out = trimmed(command.usage) + "\n";
  if (!command.description.empty()) out += "\n" + trimmed(command.description) + "\n";
  out += "\noptions:\n";
  for (const OptionSpec& o : command.options) out += help_entry(o);
  out += help_entry(flag_option("-h, --help", "this help"));
  if (!command.epilogue.empty()) out += command.epilogue;
  if (!out.empty() && out.back() != '\n') out += "\n";
  return out;
}

bool ParsedOptions::given(const std::string& name) const { return given_.count(name) != 0; }

bool ParsedOptions::has(const std::string& name) const {
  return given_.count(name) != 0 || defaults_.count(name) != 0;
}

std::pair<std::size_t, std::size_t> ParsedOptions::shard(const std::string& name) const {
  return has(name) ? value(name).shard : std::pair<std::size_t, std::size_t>{0, 1};
}

const OptionValue& ParsedOptions::value(const std::string& name) const {
  if (const auto it = given_.find(name); it != given_.end()) return it->second;
  if (const auto it = defaults_.find(name); it != defaults_.end()) return it->second;
  throw std::logic_error("option " + name + " has no value and no default");
}

ParsedOptions parse_options(const CommandSpec& command, int argc, const char* const* argv) {
  ParsedOptions parsed;
  for (const OptionSpec& o : command.options) {
    if (o.default_value.empty()) continue;
    // A default is parsed like a given value: a table whose default breaks its own rule fails
    // on every run (a programming error, caught by the tests).
    try {
      parsed.defaults_[o.name] = parse_value(command, o, o.default_value);
    } catch (const UsageError& e) {
      throw std::logic_error(std::string("the option table's default is invalid: ") + e.what());
    }
  }
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      parsed.help_ = true;
      return parsed;
    }
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& o : command.options)
      if (o.name == a) spec = &o;
    if (!spec) {
      if (a.size() > 1 && a[0] == '-')
        throw UsageError(command.name + ": unknown option '" + a + "' (see exactccd " + command.name + " --help)");
      parsed.positionals_.push_back(a);
      continue;
    }
    if (spec->type == ValueType::flag) {
      parsed.given_[spec->name] = OptionValue{};
      continue;
    }
    if (i + 1 >= argc) throw UsageError(command.name + ": option " + a + " needs a value");
    parsed.given_[spec->name] = parse_value(command, *spec, argv[++i]);
  }
  for (const OptionSpec& o : command.options)
    if (o.required && !parsed.given(o.name))
      throw UsageError(command.name + ": " + o.name + " " + o.value_name + " is required (see exactccd " +
                       command.name + " --help)");
  return parsed;
}

std::optional<long long> parse_integer_strictly(const std::string& s) {
  if (s.empty()) return std::nullopt;
  const std::size_t digits_from = s[0] == '-' ? 1 : 0;
  if (digits_from == s.size()) return std::nullopt;
  for (std::size_t i = digits_from; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return std::nullopt;
  long long n = 0;
  const char* last = s.data() + s.size();
  const auto [end, error] = std::from_chars(s.data(), last, n);
  if (error != std::errc() || end != last) return std::nullopt;
  return n;
}

}  // namespace exactccd::cli
