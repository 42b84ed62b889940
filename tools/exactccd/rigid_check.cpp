// exactccd check --motion rigid: the oracle on rigid query files.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "exactccd/rigid.hpp"
#include "io/input_file.hpp"
#include "rigid/rigid_layout.hpp"
#include "rigid_cli.hpp"

namespace exactccd::cli {

OptionSpec motion_option() {
  return choice_option("--motion", "MODEL", {"linear", "rigid"}, "linear",
                       "linear: every vertex on a straight line (benchmark CSV files); rigid: rigid bodies\n"
                       "turning and moving (files of one query per line, 41 comma-separated numbers: cA0 (3),\n"
                       "qA0 (4: w x y z), cA1 (3), qA1 (4), cB0, qB0, cB1, qB1, the body points (vf: p of A,\n"
                       "a b c of B; ee: a0 a1 of A, b0 b1 of B), the truth 0 or 1; '#' starts a comment line)");
}

bool rigid_motion(const ParsedOptions& options) { return options.text("--motion") == "rigid"; }

QueryKind rigid_kind(const std::optional<QueryKind>& given, const std::string& path) {
  const QueryKind vf = query_kind<kinds::VertexFace>(), ee = query_kind<kinds::EdgeEdge>();
  std::optional<QueryKind> kind = given ? given : kind_from_path(path);
  if (!kind) throw UsageError("cannot infer the query kind of '" + path + "' (no 'vertex-face' or 'edge-edge' in the path): pass --kind vf|ee");
  if (*kind != vf && *kind != ee)
    throw UsageError("--motion rigid answers the kinds vf and ee, not " + kind_name(*kind));
  return *kind;
}

RigidDataset load_rigid_dataset(const std::string& path, const std::optional<QueryKind>& kind) {
  RigidDataset d;
  d.path = path;
  d.kind = rigid_kind(kind, path);
  io::InputFile file(path);
  d.queries = io::read_rigid_csv(file.stream(), path);
  file.check_read();
  if (d.queries.size() == 0) throw io::InputError(path, "no queries (an empty rigid query file)");
  return d;
}

std::optional<TimeInterval> run_rigid_query(const RigidDataset& d, std::size_t i, Method method, StageCounters* counters,
                                            bool want_toi, const CcdParams& params) {
  const double* x = d.queries.numbers[i].data();
  StageCounters ignored;
  StageCounters& c = counters ? *counters : ignored;
  if (d.kind == query_kind<kinds::VertexFace>()) {
    const auto q = rigid::from_numbers<RigidVertexFaceQuery>(x);
    if (want_toi) return rigid_vertex_face_toi(q, params, method, c);
    return rigid_vertex_face_ccd(q, params, method, c) ? std::optional(TimeInterval{}) : std::nullopt;
  }
  const auto q = rigid::from_numbers<RigidEdgeEdgeQuery>(x);
  if (want_toi) return rigid_edge_edge_toi(q, params, method, c);
  return rigid_edge_edge_ccd(q, params, method, c) ? std::optional(TimeInterval{}) : std::nullopt;
}

Method rigid_method(tools::Method m) {
  if (m == tools::Method::filtered) return Method::filtered;
  if (m == tools::Method::exact) return Method::exact;
  throw UsageError("--motion rigid: --method " + method_name(m) +
                   " is a baseline for linear queries; rigid queries take filtered or exact");
}

int run_rigid_check(const ParsedOptions& options) {
  const std::optional<QueryKind> kind = kind_of(options);
  const Method method = rigid_method(parse_method(options.text("--method")));
  const bool answers = options.flag("--answers"), stats = options.flag("--stats"), json = options.flag("--json");
  const bool want_toi = options.flag("--toi");
  const CcdParams params = separation_params(options);
  const BatchOptions batch = batch_options(options);
  const std::vector<std::string>& files = options.positionals();
  if (files.empty()) throw UsageError("check: no input file (see exactccd check --help)");
  if (json && answers) throw UsageError("check: --json and --answers exclude each other");
  if (options.given("--truth")) throw UsageError("check: --truth is for linear query files (rigid files have their truth column)");

  std::vector<RigidDataset> datasets;  // every file parsed before anything is printed
  for (const std::string& f : files) datasets.push_back(load_rigid_dataset(f, kind));
  std::size_t all_queries = 0;
  for (const RigidDataset& d : datasets) all_queries += d.queries.size();
  const auto [shard_begin, shard_end] = batch.shard_range(all_queries);

  const bool table = !answers && !json;
  std::string json_items;
  std::size_t total_queries = 0, total_positives = 0, total_fp = 0, total_fn = 0;
  double total_seconds = 0;
  if (table) print_check_header(params);
  std::size_t offset = 0;
  for (const RigidDataset& d : datasets) {
    const std::size_t n = d.queries.size();
    const std::size_t begin = std::clamp(shard_begin, offset, offset + n) - offset;
    const std::size_t end = std::clamp(shard_end, offset, offset + n) - offset;
    offset += n;
    if (begin == end) continue;
    std::vector<StageCounters> counters(end - begin);
    std::vector<std::optional<TimeInterval>> result(end - begin);
    const double start = now_seconds();
    parallel_for(begin, end, batch.threads, [&](std::size_t i) {
      result[i - begin] = run_rigid_query(d, i, method, &counters[i - begin], want_toi, params);
    }, "check");
    const double seconds = now_seconds() - start;
    StageCounters stages;
    for (const StageCounters& c : counters) stages += c;
    std::size_t positives = 0, fp = 0, fn = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const bool r = result[i - begin].has_value(), truth = d.queries.truth[i];
      positives += truth;
      fp += r && !truth;
      fn += !r && truth;
    }
    const double us = 1e6 * seconds / static_cast<double>(end - begin);
    const StageCounts rigid_stages{{"separating_direction", stages.separating_direction},
                                   {"interval", stages.interval},
                                   {"integer", stages.integer},
                                   {"exact", stages.exact}};
    const CheckRecord record{d.path, kind_name(d.kind), "rigid", method == Method::filtered ? "filtered" : "exact",
                             end - begin, positives, fp, fn, us, rigid_stages};
    if (answers)
      print_answers(result, want_toi);
    else if (json)
      append_json_record(json_items, record);
    else
      print_check_row(record, stats && method == Method::filtered, params);
    total_queries += end - begin, total_positives += positives, total_fp += fp, total_fn += fn;
    total_seconds += seconds;
  }
  if (json) std::printf("[\n%s\n]\n", json_items.c_str());
  if (table) {
    const CheckRecord sum{"total", "", nullptr, "", total_queries, total_positives, total_fp, total_fn,
                          total_queries ? 1e6 * total_seconds / static_cast<double>(total_queries) : 0.0, {}};
    print_check_row(sum, false, params);
  }
  return kExitOk;
}

}  // namespace exactccd::cli
