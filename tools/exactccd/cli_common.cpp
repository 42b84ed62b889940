#include "cli_common.hpp"

#include <fstream>

namespace exactccd::cli {

QueryKind parse_kind(const std::string& s) {
  if (s == "vf" || s == "vertex-face") return QueryKind::vertex_face;
  if (s == "ee" || s == "edge-edge") return QueryKind::edge_edge;
  throw UsageError("unknown kind '" + s + "' (expected vf or ee)");
}

std::string kind_name(QueryKind k) { return k == QueryKind::vertex_face ? "vf" : "ee"; }

std::optional<QueryKind> kind_from_path(const std::string& path) {
  if (path.find("vertex-face") != std::string::npos) return QueryKind::vertex_face;
  if (path.find("edge-edge") != std::string::npos) return QueryKind::edge_edge;
  return std::nullopt;
}

Method parse_method(const std::string& s) {
  if (s == "filtered") return Method::filtered;
  if (s == "exact") return Method::exact;
  if (s == "naive") return Method::naive;
  throw UsageError("unknown method '" + s + "' (expected filtered, exact or naive)");
}

std::string method_name(Method m) {
  switch (m) {
    case Method::filtered: return "filtered";
    case Method::exact: return "exact";
    case Method::naive: return "naive";
  }
  return "?";
}

Dataset load_dataset(const std::string& path, std::optional<QueryKind> kind) {
  if (!kind) kind = kind_from_path(path);
  if (!kind)
    throw UsageError("cannot infer the query kind of '" + path +
                     "' (no 'vertex-face' or 'edge-edge' in the path): pass --kind vf|ee");
  std::ifstream in(path);
  if (!in) throw UsageError("cannot open '" + path + "'");
  Dataset d;
  d.path = path;
  d.name = path;
  d.kind = *kind;
  d.queries = io::read_benchmark_csv(in, path);
  d.doubles.reserve(d.queries.size());
  for (const auto& rows : d.queries.rows) d.doubles.push_back(io::exact_double_rows(rows));
  return d;
}

namespace {

std::array<Vec3, 8> rounded_rows(const std::array<RationalVec3, 8>& rows) {
  std::array<Vec3, 8> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    out[i] = {rows[i].x.get_d(), rows[i].y.get_d(), rows[i].z.get_d()};
  return out;
}

std::optional<TimeInterval> collides_placeholder(bool collides) {
  return collides ? std::optional<TimeInterval>(TimeInterval{}) : std::nullopt;
}

}  // namespace

std::optional<TimeInterval> run_query(const Dataset& d, std::size_t i, Method method,
                                      StageCounters* counters, bool want_toi) {
  const bool vf = d.kind == QueryKind::vertex_face;
  const auto& exact_rows = d.doubles[i];
  if (!exact_rows && method != Method::naive) {  // not doubles: the rational exact path
    if (counters) ++counters->exact;
    const auto& r = d.queries.rows[i];
    if (vf) {
      const auto q = from_rows<RationalVertexFaceQuery>(r);
      return want_toi ? vertex_face_toi(q) : collides_placeholder(vertex_face_ccd(q));
    }
    const auto q = from_rows<RationalEdgeEdgeQuery>(r);
    return want_toi ? edge_edge_toi(q) : collides_placeholder(edge_edge_ccd(q));
  }
  const std::array<Vec3, 8> rows = exact_rows ? *exact_rows : rounded_rows(d.queries.rows[i]);
  StageCounters unused;
  StageCounters& c = counters ? *counters : unused;
  if (vf) {
    const auto q = from_rows<VertexFaceQuery>(rows);
    return want_toi ? vertex_face_toi(q, method, c) : collides_placeholder(vertex_face_ccd(q, method, c));
  }
  const auto q = from_rows<EdgeEdgeQuery>(rows);
  return want_toi ? edge_edge_toi(q, method, c) : collides_placeholder(edge_edge_ccd(q, method, c));
}

std::string option_value(int argc, char** argv, int& i) {
  if (i + 1 >= argc) throw UsageError(std::string("option ") + argv[i] + " needs a value");
  return argv[++i];
}

}  // namespace exactccd::cli
