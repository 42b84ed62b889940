// The exactccd option parser (tools/exactccd/options): every value type, its range, the strict
// integer syntax (no prefixes such as "2x", no "1e9" for an integer, no wrapped negatives),
// --shard forms, defaults, required options, and the help text generated from the same table.
#include <gtest/gtest.h>

#include <climits>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "options.hpp"

namespace exactccd::cli {
namespace {

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "demo";
    c.usage = "usage: exactccd demo [options] FILE...";
    c.description = "A command to test the parser.\n";
    c.options = {
        flag_option("--json", "print JSON"),
        integer_option("--threads", "N", 1, 1024, "1", "threads"),
        integer_option("--offset", "K", -5, 5, "", "an offset that may be negative"),
        integer_option("--count", "N", 0, LLONG_MAX, "", "unbounded above"),
        unsigned64_option("--seed", "S", "1", "seed"),
        real_option("--scale", "X", 0.5, 4.0, "1", "a scale"),
        text_option("--out", "FILE", "", "output file"),
        choice_option("--kind", "vf|ee", {"vf", "ee"}, "", "kind"),
        choice_option("--method", "NAME", {"filtered", "exact", "naive"}, "filtered", "method"),
        choice_list_option("--methods", "LIST", {"filtered", "exact", "naive"}, "filtered,exact", "methods"),
        shard_option("--shard", 100, "a block of the run"),
    };
    c.epilogue = "exit codes: 0 ran.\n";
    return c;
  }();
  return spec;
}

ParsedOptions parse(std::vector<std::string> args, const CommandSpec& c = command()) {
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  return parse_options(c, static_cast<int>(argv.size()), argv.data());
}

/// The usage error message of parsing args ("" when they parse).
std::string error_of(std::vector<std::string> args, const CommandSpec& c = command()) {
  try {
    parse(std::move(args), c);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, DefaultsComeFromTheTable) {
  const ParsedOptions o = parse({});
  EXPECT_FALSE(o.help());
  EXPECT_FALSE(o.flag("--json"));
  EXPECT_EQ(o.integer("--threads"), 1);
  EXPECT_FALSE(o.given("--threads"));
  EXPECT_TRUE(o.has("--threads"));
  EXPECT_FALSE(o.has("--offset"));
  EXPECT_EQ(o.unsigned64("--seed"), 1u);
  EXPECT_EQ(o.real("--scale"), 1.0);
  EXPECT_EQ(o.text("--method"), "filtered");
  EXPECT_EQ(o.list("--methods"), (std::vector<std::string>{"filtered", "exact"}));
  EXPECT_EQ(o.shard("--shard"), (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_THROW(o.integer("--offset"), std::logic_error);  // no value and no default
}

TEST(Options, ValuesPositionalsAndTheLastOccurrenceWins) {
  const ParsedOptions o = parse({"a.csv", "--threads", "8", "--json", "b.csv", "--threads", "1024", "--offset",
                                 "-5", "--seed", "18446744073709551615", "--scale", "2.5", "--out", "x.json",
                                 "--kind", "ee", "--methods", "naive,exact", "--shard", "3/4", "-"});
  EXPECT_EQ(o.positionals(), (std::vector<std::string>{"a.csv", "b.csv", "-"}));
  EXPECT_TRUE(o.flag("--json"));
  EXPECT_EQ(o.integer("--threads"), 1024);
  EXPECT_EQ(o.integer("--offset"), -5);
  EXPECT_EQ(o.unsigned64("--seed"), 18446744073709551615u);
  EXPECT_EQ(o.real("--scale"), 2.5);
  EXPECT_EQ(o.text("--out"), "x.json");
  EXPECT_EQ(o.text("--kind"), "ee");
  EXPECT_EQ(o.list("--methods"), (std::vector<std::string>{"naive", "exact"}));
  EXPECT_EQ(o.shard("--shard"), (std::pair<std::size_t, std::size_t>{3, 4}));
  EXPECT_EQ(parse({"--methods", "all"}).list("--methods"),
            (std::vector<std::string>{"filtered", "exact", "naive"}));
  EXPECT_EQ(parse({"--count", "9223372036854775807"}).integer("--count"), LLONG_MAX);
}

TEST(Options, IntegersAreStrictAndInRange) {
  const std::string needs = "demo: --threads needs an integer in 1..1024, not ";
  EXPECT_EQ(error_of({"--threads", "0"}), needs + "'0'");
  EXPECT_EQ(error_of({"--threads", "1025"}), needs + "'1025'");
  EXPECT_EQ(error_of({"--threads", "100000"}), needs + "'100000'");
  EXPECT_EQ(error_of({"--threads", "-1"}), needs + "'-1'");  // a value, not an unknown option
  for (const char* bad : {"2x", "x2", "1e9", "1.0", "0x10", "+2", " 2", "2 ", "", "-", "--2", "4294967297",
                          "99999999999999999999999"})
    EXPECT_EQ(error_of({"--threads", bad}), needs + "'" + bad + "'") << bad;
  EXPECT_EQ(error_of({"--offset", "-6"}), "demo: --offset needs an integer in -5..5, not '-6'");
  EXPECT_EQ(error_of({"--count", "-1"}), "demo: --count needs an integer >= 0, not '-1'");
  EXPECT_EQ(error_of({"--count", "9223372036854775808"}),
            "demo: --count needs an integer >= 0, not '9223372036854775808'");
}

TEST(Options, Unsigned64RejectsNegativesAndPrefixes) {
  for (const char* bad : {"-1", "1e9", "18446744073709551616", "7x", "", "+1"})
    EXPECT_EQ(error_of({"--seed", bad}),
              std::string("demo: --seed needs an integer in 0..18446744073709551615, not '") + bad + "'")
        << bad;
  EXPECT_EQ(parse({"--seed", "0"}).unsigned64("--seed"), 0u);
}

TEST(Options, RealsAreFiniteAndInRange) {
  EXPECT_EQ(parse({"--scale", "4"}).real("--scale"), 4.0);
  EXPECT_EQ(parse({"--scale", "5e-1"}).real("--scale"), 0.5);
  // Hexadecimal literals as in the data files (strtod's forms): exact powers of two and more.
  EXPECT_EQ(parse({"--scale", "0x1p0"}).real("--scale"), 1.0);
  EXPECT_EQ(parse({"--scale", "0x1.8p1"}).real("--scale"), 3.0);
  EXPECT_EQ(parse({"--scale", "0X1.fffffffffffffp-1"}).real("--scale"), 0x1.fffffffffffffp-1);
  for (const char* bad : {"4.0001", "0.25", "nan", "inf", "1x", "", "0x1p3", "0x", "0x-1p0", "0xg", "0x1p0x",
                          "-0x1p0", "--0x1p0"})
    EXPECT_NE(error_of({"--scale", bad}).find("demo: --scale needs a finite number in [0.5, 4], not '"),
              std::string::npos)
        << bad;
}

TEST(Options, ChoicesAndLists) {
  EXPECT_EQ(error_of({"--kind", "xx"}), "demo: --kind needs one of vf, ee, not 'xx'");
  EXPECT_EQ(error_of({"--method", "Exact"}), "demo: --method needs one of filtered, exact, naive, not 'Exact'");
  const std::string list = "demo: --methods needs a comma-separated list of filtered, exact, naive or all, not ";
  for (const char* bad : {"", ",", "exact,", ",exact", "exact,,naive", "exact,bogus", "all,exact"})
    EXPECT_EQ(error_of({"--methods", bad}), list + "'" + bad + "'") << bad;
  EXPECT_EQ(error_of({"--out", ""}), "demo: --out needs a non-empty value, not ''");
}

TEST(Options, ShardForms) {
  EXPECT_EQ(parse({"--shard", "0/1"}).shard("--shard"), (std::pair<std::size_t, std::size_t>{0, 1}));
  EXPECT_EQ(parse({"--shard", "99/100"}).shard("--shard"), (std::pair<std::size_t, std::size_t>{99, 100}));
  for (const char* bad : {"3/2", "2/2", "0/0", "-1/2", "1/-2", "1", "1/", "/2", "1/2x", "1x/2", "1/2/3", "0.5/2",
                          "0/101", "1 /2", ""})
    EXPECT_EQ(error_of({"--shard", bad}),
              std::string("demo: --shard needs I/N with 0 <= I < N <= 100, not '") + bad + "'")
        << bad;
}

TEST(Options, UnknownMissingAndRequired) {
  EXPECT_EQ(error_of({"--frobnicate"}), "demo: unknown option '--frobnicate' (see exactccd demo --help)");
  EXPECT_EQ(error_of({"-x"}), "demo: unknown option '-x' (see exactccd demo --help)");
  EXPECT_EQ(error_of({"--threads"}), "demo: option --threads needs a value");
  CommandSpec c = command();
  c.options.push_back(required(text_option("--answers", "FILE", "", "their answers")));
  EXPECT_EQ(error_of({}, c), "demo: --answers FILE is required (see exactccd demo --help)");
  EXPECT_EQ(error_of({"x", "--json"}, c), "demo: --answers FILE is required (see exactccd demo --help)");
  EXPECT_EQ(parse({"--answers", "a.txt"}, c).text("--answers"), "a.txt");
}

TEST(Options, HelpStopsParsing) {
  EXPECT_TRUE(parse({"--help"}).help());
  EXPECT_TRUE(parse({"a", "-h", "--threads", "0"}).help());  // nothing after --help is parsed
  EXPECT_THROW(parse({"--threads", "0", "--help"}), UsageError);  // but what comes before is
}

TEST(Options, InvalidDefaultInTheTableIsAProgrammingError) {
  CommandSpec c = command();
  c.options.push_back(integer_option("--bad", "N", 1, 10, "11", "a default outside its own range"));
  EXPECT_THROW(parse({}, c), std::logic_error);
}

TEST(Options, HelpIsGeneratedFromTheTable) {
  const std::string help = help_text(command());
  EXPECT_EQ(help.rfind("usage: exactccd demo [options] FILE...\n\nA command to test the parser.\n\noptions:\n", 0), 0u)
      << help;
  // Every option of the table, with its value name, range or choices and default.
  for (const OptionSpec& o : command().options) EXPECT_NE(help.find("  " + o.name), std::string::npos) << o.name;
  EXPECT_NE(help.find("  --threads N         threads (N in 1..1024; default 1)\n"), std::string::npos) << help;
  EXPECT_NE(help.find("  --offset K          an offset that may be negative (K in -5..5)\n"), std::string::npos);
  EXPECT_NE(help.find("  --count N           unbounded above (N >= 0)\n"), std::string::npos);
  EXPECT_NE(help.find("  --kind vf|ee        kind\n"), std::string::npos);
  EXPECT_NE(help.find("  --method NAME       method (one of filtered, exact, naive; default filtered)\n"),
            std::string::npos);
  EXPECT_NE(help.find("  --shard I/N         a block of the run (0 <= I < N <= 100)\n"), std::string::npos);
  EXPECT_NE(help.find("  --json              print JSON\n"), std::string::npos);
  EXPECT_NE(help.find("  -h, --help          this help\nexit codes: 0 ran.\n"), std::string::npos);
  // The parser accepts exactly what the help states: the bounds and the default.
  EXPECT_EQ(parse({"--threads", "1024"}).integer("--threads"), 1024);
  EXPECT_NE(error_of({"--threads", "1025"}), "");
}

TEST(Options, ParseIntegerStrictly) {
  EXPECT_EQ(parse_integer_strictly("0"), 0);
  EXPECT_EQ(parse_integer_strictly("-12"), -12);
  EXPECT_EQ(parse_integer_strictly("007"), 7);
  EXPECT_EQ(parse_integer_strictly("-9223372036854775808"), LLONG_MIN);
  for (const char* bad : {"", "-", "+1", "1e3", "1.", "12a", " 1", "9223372036854775808"})
    EXPECT_FALSE(parse_integer_strictly(bad).has_value()) << bad;
}

// The real subcommands' shared options: --threads is 1..kMaxThreads everywhere.
TEST(Options, BatchOptionsOfTheSubcommands) {
  CommandSpec c;
  c.name = "check";
  c.options = batch_option_specs();
  const BatchOptions b = batch_options(parse({"--threads", "3", "--shard", "1/2"}, c));
  EXPECT_EQ(b.threads, 3u);
  EXPECT_EQ(b.shard_index, 1u);
  EXPECT_EQ(b.shard_count, 2u);
  EXPECT_EQ(b.shard_range(10), (std::pair<std::size_t, std::size_t>{5, 10}));
  EXPECT_EQ(batch_options(parse({}, c)).threads, 1u);
  EXPECT_NO_THROW(parse({"--threads", std::to_string(kMaxThreads)}, c));
  EXPECT_THROW(parse({"--threads", std::to_string(kMaxThreads + 1)}, c), UsageError);
}

TEST(KindFromPath, LongNamesAndTheDatasetsShortNames) {
  const auto name = [](const std::string& p) {
    const std::optional<QueryKind> k = kind_from_path(p);
    return k ? kind_name(*k) : std::string("none");
  };
  EXPECT_EQ(name("data/vertex-face.csv"), "vf");
  EXPECT_EQ(name("edge-edge/run-vertex-face.csv"), "vf");
  EXPECT_EQ(name("x/edge-edge-2d.csv"), "ee2");
  EXPECT_EQ(name("x/point-edge-2d-small.csv"), "pe2");
  EXPECT_EQ(name("cloth-funnel/queries/227vf.csv"), "vf");
  EXPECT_EQ(name("cloth-funnel/queries/227ee.csv"), "ee");
  EXPECT_EQ(name("vertex-face/227ee.csv"), "ee");  // the file name wins
  EXPECT_EQ(name("ee.csv"), "ee");
  EXPECT_EQ(name("q-vf.csv"), "vf");
  EXPECT_EQ(name("coffee.csv"), "none");  // 'ee' after a letter
  EXPECT_EQ(name("vf/queries.csv"), "none");  // folders do not count for the short names
  EXPECT_EQ(name("227vf.csv/x.csv"), "none");
}

TEST(KindFromPath, TruthFoundByName) {
  EXPECT_EQ(truth_path_by_name("d/cloth-funnel/queries/227vf.csv"), "d/cloth-funnel/mma_bool/227vf_mma_bool.json");
}

}  // namespace
}  // namespace exactccd::cli
