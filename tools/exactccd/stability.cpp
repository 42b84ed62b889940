// exactccd stability: sweeps the degenerate families over the perturbation exponent k and
// writes each method's false-positive and false-negative rates against the exact answer (by
// construction where the family knows it, else Method::exact).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "fuzz/families.hpp"
#include "subcommands.hpp"

namespace exactccd::cli {
namespace {

constexpr const char* kHelp = R"(usage: exactccd stability [options]

Sweeps every degenerate family (fuzz/families.hpp: a degenerate configuration perturbed by
2^-k times the scene scale, towards or away from contact) over k = K_MIN..K_MAX, plus the
unperturbed configuration (k written as -1), and writes for every method the false-positive
and false-negative counts and rates against the exact answer, as CSV (the answer known by
construction where the family knows it, else the CGAL reference Method::exact; so the exact
methods' own rows are a check, not a tautology):
  family,kind,method,k,queries,fp,fn,fp_rate,fn_rate
Instances alternate between the two directions; each is seeded from (seed, family, k, i), so
a run is reproducible and independent of --threads.

options:
  --families LIST      comma-separated family names, or all (default)
  --methods LIST       comma-separated methods or all (default): naive, naive-tolerance, mpfr24,
                       mpfr53, mpfr113, mpfr256, filtered, exact
  --k-min K, --k-max K range of k (default 0..60)
  --instances N        instances per (family, k) (default 20)
  --seed S             base seed (default 1)
  --out FILE           write the CSV there (default: stdout)
%s  -h, --help           this help
exit codes: 0 ran, 2 bad usage, 1 internal error.
)";

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string x; std::getline(ss, x, ',');)
    if (!x.empty()) out.push_back(x);
  return out;
}

bool answer(const families::AnyQuery& q, Method m) {
  return std::visit(
      [m](const auto& x) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, VertexFaceQuery>)
          return vertex_face_ccd(x, m);
        else
          return edge_edge_ccd(x, m);
      },
      q);
}

struct Cell {  // one (family, k): counts per method
  std::vector<std::size_t> fp, fn;
  std::size_t queries = 0;
};

}  // namespace

int run_stability(int argc, char** argv) {
  std::string families_list = "all", methods_list = "all", out_path;
  int k_min = 0, k_max = 60, instances = 20;
  std::uint64_t seed = 1;
  BatchOptions batch;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::printf(kHelp, kBatchOptionsHelp);
      return kExitOk;
    } else if (batch.parse(argc, argv, i)) {
      continue;
    } else if (a == "--families") {
      families_list = option_value(argc, argv, i);
    } else if (a == "--methods") {
      methods_list = option_value(argc, argv, i);
    } else if (a == "--k-min") {
      k_min = std::stoi(option_value(argc, argv, i));
    } else if (a == "--k-max") {
      k_max = std::stoi(option_value(argc, argv, i));
    } else if (a == "--instances") {
      instances = std::stoi(option_value(argc, argv, i));
    } else if (a == "--seed") {
      seed = std::stoull(option_value(argc, argv, i));
    } else if (a == "--out") {
      out_path = option_value(argc, argv, i);
    } else {
      throw UsageError("stability: unknown argument '" + a + "' (see exactccd stability --help)");
    }
  }
  if (k_min < 0 || k_max < k_min || instances < 1)
    throw UsageError("stability: need 0 <= k-min <= k-max and instances >= 1");

  std::vector<const families::Family*> fams;
  if (families_list == "all") {
    for (const auto& f : families::all_families()) fams.push_back(&f);
  } else {
    for (const std::string& n : split(families_list)) {
      const families::Family* f = families::find_family(n);
      if (!f) throw UsageError("stability: unknown family '" + n + "'");
      fams.push_back(f);
    }
  }
  std::vector<Method> methods;
  if (methods_list == "all") {
    methods = all_methods();
  } else {
    for (const std::string& n : split(methods_list)) methods.push_back(parse_method(n));
  }

  // Tasks: (family, k) pairs, k = -1 for the unperturbed configuration.
  std::vector<std::pair<const families::Family*, int>> tasks;
  for (const auto* f : fams) {
    tasks.push_back({f, families::kUnperturbed});
    for (int k = k_min; k <= k_max; ++k) tasks.push_back({f, k});
  }
  const auto [begin, end] = batch.shard_range(tasks.size());
  std::vector<Cell> cells(tasks.size());
  parallel_for(begin, end, batch.threads, [&](std::size_t t) {
    const auto& [family, k] = tasks[t];
    Cell& cell = cells[t];
    cell.fp.assign(methods.size(), 0);
    cell.fn.assign(methods.size(), 0);
    for (int i = 0; i < instances; ++i) {
      std::seed_seq s{seed, static_cast<std::uint64_t>(t), static_cast<std::uint64_t>(i)};
      std::mt19937_64 rng(s);
      const families::Instance inst = family->make(k, i % 2 == 0, rng);
      const bool reference = answer(inst.query, Method::exact);  // the CGAL reference
      const bool truth = inst.expected.value_or(reference);       // the construction's, if known
      ++cell.queries;
      for (std::size_t m = 0; m < methods.size(); ++m) {
        const bool got = methods[m] == Method::exact ? reference : answer(inst.query, methods[m]);
        cell.fp[m] += got && !truth;
        cell.fn[m] += !got && truth;
      }
    }
  }, "stability");

  std::ofstream file;
  if (!out_path.empty()) {
    file.open(out_path);
    if (!file) throw UsageError("stability: cannot write '" + out_path + "'");
  }
  std::ostream& out = out_path.empty() ? std::cout : file;
  out << "family,kind,method,k,queries,fp,fn,fp_rate,fn_rate\n";
  for (std::size_t t = begin; t < end; ++t) {
    const auto& [family, k] = tasks[t];
    const Cell& c = cells[t];
    for (std::size_t m = 0; m < methods.size(); ++m)
      out << family->name << ',' << (family->vertex_face ? "vf" : "ee") << ',' << method_name(methods[m])
          << ',' << k << ',' << c.queries << ',' << c.fp[m] << ',' << c.fn[m] << ','
          << static_cast<double>(c.fp[m]) / c.queries << ',' << static_cast<double>(c.fn[m]) / c.queries
          << '\n';
  }
  return kExitOk;
}

}  // namespace exactccd::cli
