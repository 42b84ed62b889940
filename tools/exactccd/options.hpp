// The typed option parser of every exactccd subcommand: a subcommand declares its options once,
// in a table (name, value type with its range or choices, default, help text), and both the
// parser and the --help text are generated from that table, so they cannot drift apart.
// Every malformed or out-of-range value is a UsageError (exit code 2) naming the option.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace exactccd::cli {

/// The kind of value an option takes.
enum class ValueType {
  flag,         ///< no value: present or not
  integer,      ///< a base-10 integer (optional '-', digits only) in [min, max]
  unsigned64,   ///< a base-10 integer in [0, 2^64 - 1] (seeds)
  real,         ///< a finite decimal number in [real_min, real_max]
  text,         ///< any non-empty string (a path, a list checked by the subcommand)
  choice,       ///< one of `choices`
  choice_list,  ///< a comma-separated list of `choices`, or "all"
  shard,        ///< I/N with 0 <= I < N <= max (integers)
};

/// One option of a subcommand: what it is called, what it takes, what --help says about it.
struct OptionSpec {
  std::string name;                  ///< "--threads"
  ValueType type = ValueType::flag;  ///< the value's type
  std::string value_name;            ///< shown in the help after the name ("N"); empty for flags
  std::string help;                  ///< help text; '\n' starts an indented continuation line
  long long min = 0, max = 0;        ///< integer range (inclusive); shard: the largest N in max
  double real_min = 0, real_max = 0; ///< real range (inclusive)
  std::vector<std::string> choices;  ///< choice and choice_list: the accepted values
  std::string default_value;         ///< the value when absent (parsed like a given one); may be empty
  bool required = false;             ///< absent is a usage error
};

/// A flag (`--json`).
OptionSpec flag_option(const std::string& name, const std::string& help);
/// An integer option in [min, max] with a default (empty: none).
OptionSpec integer_option(const std::string& name, const std::string& value_name, long long min,
                          long long max, const std::string& default_value, const std::string& help);
/// An unsigned 64-bit integer option (a seed) with a default.
OptionSpec unsigned64_option(const std::string& name, const std::string& value_name,
                             const std::string& default_value, const std::string& help);
/// A finite real option in [min, max] with a default (empty: none).
OptionSpec real_option(const std::string& name, const std::string& value_name, double min, double max,
                       const std::string& default_value, const std::string& help);
/// A string option (a path, a list) with a default (empty: none).
OptionSpec text_option(const std::string& name, const std::string& value_name,
                       const std::string& default_value, const std::string& help);
/// An option taking one of `choices`, with a default (empty: none).
OptionSpec choice_option(const std::string& name, const std::string& value_name,
                         std::vector<std::string> choices, const std::string& default_value,
                         const std::string& help);
/// An option taking a comma-separated list of `choices` or "all", with a default.
OptionSpec choice_list_option(const std::string& name, const std::string& value_name,
                              std::vector<std::string> choices, const std::string& default_value,
                              const std::string& help);
/// A shard option I/N (0 <= I < N <= max_count); absent means the whole run (0/1).
OptionSpec shard_option(const std::string& name, long long max_count, const std::string& help);

/// A spec with `required` set.
OptionSpec required(OptionSpec spec);

/// A subcommand's command line: its usage lines, description, options and closing text.
struct CommandSpec {
  std::string name;         ///< "check"; prefixes every usage error ("check: ...")
  std::string usage;        ///< "usage: exactccd check [options] FILE.csv..." (may be several lines)
  std::string description;  ///< paragraphs between the usage and the options
  std::vector<OptionSpec> options;  ///< every option but -h/--help, which every command has
  std::string epilogue;     ///< text after the options (output format, exit codes)
};

/// The --help text of a command: usage, description, "options:" with one entry per option of
/// the table (name, value name, help, then what the table says of the value: its range or
/// choices and its default), "-h, --help", then the epilogue.
std::string help_text(const CommandSpec& command);

/// A parsed value.
struct OptionValue {
  std::string text;            ///< as written (or the default)
  long long integer = 0;       ///< integer
  std::uint64_t unsigned64 = 0;  ///< unsigned64
  double real = 0;             ///< real
  std::vector<std::string> list;  ///< choice_list (expanded: "all" gives every choice)
  std::pair<std::size_t, std::size_t> shard{0, 1};  ///< shard: (I, N)
};

/// The options given to one subcommand, and its positional arguments.
class ParsedOptions {
 public:
  /// Whether -h or --help was given (the command prints help_text and exits 0).
  bool help() const { return help_; }
  /// Whether the option was on the command line (defaults do not count).
  bool given(const std::string& name) const;
  /// Whether the option has a value, given or by default.
  bool has(const std::string& name) const;
  /// A flag's presence.
  bool flag(const std::string& name) const { return given(name); }
  /// An integer option's value (given or default); throws std::logic_error without either.
  long long integer(const std::string& name) const { return value(name).integer; }
  /// An unsigned 64-bit option's value.
  std::uint64_t unsigned64(const std::string& name) const { return value(name).unsigned64; }
  /// A real option's value.
  double real(const std::string& name) const { return value(name).real; }
  /// A text or choice option's value.
  const std::string& text(const std::string& name) const { return value(name).text; }
  /// A choice_list option's values ("all" expanded to every choice).
  const std::vector<std::string>& list(const std::string& name) const { return value(name).list; }
  /// A shard option's (I, N); (0, 1) when absent.
  std::pair<std::size_t, std::size_t> shard(const std::string& name) const;
  /// The arguments that are not options, in order.
  const std::vector<std::string>& positionals() const { return positionals_; }

 private:
  friend ParsedOptions parse_options(const CommandSpec&, int, const char* const*);
  const OptionValue& value(const std::string& name) const;
  bool help_ = false;
  std::map<std::string, OptionValue> given_, defaults_;
  std::vector<std::string> positionals_;
};

/// Parses argv[0..argc) against the command's table: each option once or more (the last
/// wins), its value the next argument (also when it starts with '-', so "--threads -1" is a
/// range error, not an unknown option). Stops at -h/--help. Throws UsageError ("NAME: ...")
/// on an unknown option, a missing value, a malformed or out-of-range value (a prefix such as
/// "2x", "1e9" for an integer, "-1" below the range) or a missing required option.
ParsedOptions parse_options(const CommandSpec& command, int argc, const char* const* argv);

/// parse_options for a main()-style char** argv.
inline ParsedOptions parse_options(const CommandSpec& command, int argc, char** argv) {
  return parse_options(command, argc, const_cast<const char* const*>(argv));
}

/// The integer written in `s` (optional '-', then digits only), or nullopt when s is not such an
/// integer or does not fit a long long.
std::optional<long long> parse_integer_strictly(const std::string& s);

}  // namespace exactccd::cli
