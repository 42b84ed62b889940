// exactccd stability: sweeps the degenerate families over the perturbation exponent k and
// writes each method's false-positive and false-negative rates against the exact answer (by
// construction where the family knows it, else Method::exact).
#include <cstdio>
#include <optional>
#include <iostream>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "generators/families.hpp"
#include "io/output_file.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

/// The largest perturbation exponent: 2^-1074 is the smallest positive double.
constexpr long long kMaxK = 1074;
/// The most instances per (family, k): a bound on the run time.
constexpr long long kMaxInstances = 1000000;

const CommandSpec& command() {
  static const CommandSpec spec = [] {
    CommandSpec c;
    c.name = "stability";
    c.usage = "usage: exactccd stability [options]";
    c.description =
        "Sweeps every degenerate family (tools/lib/generators/families.hpp: a degenerate configuration perturbed by\n"
        "2^-k times the scene scale, towards or away from contact) over k = K_MIN..K_MAX, plus the\n"
        "unperturbed configuration (k written as -1), and writes for every method the false-positive\n"
        "and false-negative counts and rates against the exact answer, as CSV (the answer known by\n"
        "construction where the family knows it, else the CGAL reference Method::exact; so the exact\n"
        "methods' own rows are a check, not a tautology):\n"
        "  family,kind,method,k,queries,fp,fn,fp_rate,fn_rate\n"
        "Instances alternate between the two directions; each is seeded from (seed, family, k, i), so\n"
        "a run is reproducible and independent of --threads.\n"
        "\n"
        "With --min-distance D (or --tmax T) every instance asks the separation question instead (within\n"
        "distance D at some t in [0, T]); the reference is then Method::exact at that question (the\n"
        "families' constructed answers are the contact question's), and only the exact methods answer.\n";
    c.options = {
        text_option("--families", "LIST", "all", "comma-separated family names, or all"),
        choice_list_option("--methods", "LIST", all_method_names(), "all", "the methods to run"),
        integer_option("--k-min", "K", 0, kMaxK, "0", "smallest k"),
        integer_option("--k-max", "K", 0, kMaxK, "60", "largest k (at least --k-min)"),
        integer_option("--instances", "N", 1, kMaxInstances, "20", "instances per (family, k)"),
        unsigned64_option("--seed", "S", "1", "base seed"),
        text_option("--out", "FILE", "",
                    "write the CSV there (default: stdout); written to a temporary renamed\n"
                    "when complete"),
    };
    for (OptionSpec& o : separation_option_specs()) c.options.push_back(o);
    for (OptionSpec& o : batch_option_specs()) c.options.push_back(o);
    c.epilogue = "exit codes: 0 ran, 2 bad usage, 1 internal error.\n";
    return c;
  }();
  return spec;
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string x; std::getline(ss, x, ',');)
    if (!x.empty()) out.push_back(x);
  return out;
}

/// The answer of a method to the question (the contact question when params are the defaults).
bool answer(const families::AnyQuery& q, tools::Method m, const CcdParams& params) {
  if (params.contact_over_whole_step())
    return std::visit([m](const auto& x) { return tools::ccd(x, m); }, q);
  const Method exact_method = m == tools::Method::exact ? Method::exact : Method::filtered;
  return std::visit([&](const auto& x) { return ccd(x, params, exact_method); }, q);
}

struct Cell {  // one (family, k): counts per method
  std::vector<std::size_t> fp, fn;
  std::size_t queries = 0;
};

/// The families of --families ("all" or a comma-separated list of names).
std::vector<const families::Family*> chosen_families(const std::string& list) {
  std::vector<const families::Family*> fams;
  if (list == "all") {
    for (const auto& f : families::all_families()) fams.push_back(&f);
    return fams;
  }
  for (const std::string& n : split(list)) {
    const families::Family* f = families::find_family(n);
    if (!f) throw UsageError("stability: unknown family '" + n + "'");
    fams.push_back(f);
  }
  return fams;
}

/// The methods of --methods that answer the question ("all": those that do; a baseline named at
/// another question than contact is a UsageError).
std::vector<tools::Method> chosen_methods(const ParsedOptions& options, bool contact_question) {
  std::vector<tools::Method> methods;
  for (const std::string& n : options.list("--methods")) {
    const tools::Method m = parse_method(n);
    if (!contact_question && !tools::is_exact_method(m)) {
      if (options.text("--methods") == "all") continue;  // all: the methods that answer it
      throw UsageError("stability: the baseline method " + n + " answers only the contact question");
    }
    methods.push_back(m);
  }
  return methods;
}

/// What a sweep runs: the (family, k) tasks (k = -1 for the unperturbed configuration), the
/// methods, the instances per task and the question.
struct Sweep {
  std::vector<std::pair<const families::Family*, int>> tasks;
  std::vector<tools::Method> methods;
  int instances = 0;
  std::uint64_t seed = 0;
  CcdParams params;
  bool contact_question() const { return params.contact_over_whole_step(); }
};

/// The counts of task t: each instance seeded from (seed, t, i), alternating directions.
Cell run_task(const Sweep& sweep, std::size_t t) {
  const auto& [family, k] = sweep.tasks[t];
  Cell cell;
  cell.fp.assign(sweep.methods.size(), 0);
  cell.fn.assign(sweep.methods.size(), 0);
  for (int i = 0; i < sweep.instances; ++i) {
    std::seed_seq s{sweep.seed, static_cast<std::uint64_t>(t), static_cast<std::uint64_t>(i)};
    std::mt19937_64 rng(s);
    const families::Instance inst = family->make(k, i % 2 == 0, rng);
    const bool reference = answer(inst.query, tools::Method::exact, sweep.params);  // the CGAL reference
    // The construction's answer where the family knows it (the contact question's only).
    const bool truth = sweep.contact_question() ? inst.expected.value_or(reference) : reference;
    ++cell.queries;
    for (std::size_t m = 0; m < sweep.methods.size(); ++m) {
      const tools::Method method = sweep.methods[m];
      const bool got = method == tools::Method::exact ? reference : answer(inst.query, method, sweep.params);
      cell.fp[m] += got && !truth;
      cell.fn[m] += !got && truth;
    }
  }
  return cell;
}

/// The CSV of tasks [begin, end).
std::string sweep_csv(const Sweep& sweep, const std::vector<Cell>& cells, std::size_t begin, std::size_t end) {
  std::ostringstream out;
  out << "family,kind,method,k,queries,fp,fn,fp_rate,fn_rate\n";
  for (std::size_t t = begin; t < end; ++t) {
    const auto& [family, k] = sweep.tasks[t];
    const Cell& c = cells[t];
    for (std::size_t m = 0; m < sweep.methods.size(); ++m)
      out << family->name << ',' << kind_name(parse_kind(std::string(family->kind))) << ','
          << method_name(sweep.methods[m]) << ',' << k << ',' << c.queries << ',' << c.fp[m] << ',' << c.fn[m] << ','
          << static_cast<double>(c.fp[m]) / c.queries << ',' << static_cast<double>(c.fn[m]) / c.queries << '\n';
  }
  return out.str();
}

}  // namespace

int run_stability(int argc, char** argv) {
  const ParsedOptions options = parse_options(command(), argc, argv);
  if (options.help()) {
    std::cout << help_text(command());
    return kExitOk;
  }
  const int k_min = static_cast<int>(options.integer("--k-min")), k_max = static_cast<int>(options.integer("--k-max"));
  Sweep sweep;
  sweep.instances = static_cast<int>(options.integer("--instances"));
  sweep.seed = options.unsigned64("--seed");
  const BatchOptions batch = batch_options(options);
  if (!options.positionals().empty())
    throw UsageError("stability: unknown argument '" + options.positionals()[0] + "' (see exactccd stability --help)");
  if (k_max < k_min) throw UsageError("stability: need --k-min <= --k-max");
  // An unwritable --out FILE fails now, not after the whole run.
  std::optional<io::AtomicOutputFile> file;
  if (options.has("--out")) file.emplace(options.text("--out"));
  const std::vector<const families::Family*> fams = chosen_families(options.text("--families"));
  sweep.params = separation_params(options);
  sweep.methods = chosen_methods(options, sweep.contact_question());
  for (const auto* f : fams) {
    sweep.tasks.push_back({f, families::kUnperturbed});
    for (int k = k_min; k <= k_max; ++k) sweep.tasks.push_back({f, k});
  }
  const auto [begin, end] = batch.shard_range(sweep.tasks.size());
  std::vector<Cell> cells(sweep.tasks.size());
  parallel_for(begin, end, batch.threads, [&](std::size_t t) { cells[t] = run_task(sweep, t); }, "stability");
  const std::string csv = sweep_csv(sweep, cells, begin, end);
  if (file) {
    file->stream() << csv;
    file->commit();
  } else {
    std::cout << csv;
  }
  return kExitOk;
}

}  // namespace exactccd::cli
