// Rigid motion on the command line (motion.hpp's traits; issue 24): two rigid bodies turning and
// moving from pose (c0, q0) to (c1, q1), vertex-face and edge-edge queries in the files of
// io/rigid_csv.hpp, answered by the library's filtered and exact methods (include/exactccd/rigid.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/rigid_csv.hpp"
#include "motion.hpp"

namespace exactccd::cli {

/// A loaded rigid query file.
struct RigidDataset {
  std::string path;
  QueryKind kind;  ///< vf or ee
  io::RigidQueries queries;
};

/// The rigid motion model (motion.hpp).
struct RigidMotion {
  static constexpr const char* name = "rigid";
  using Dataset = RigidDataset;

  /// Reads a rigid file (its kind: --kind vf|ee, else vertex-face / edge-edge in the path; a
  /// UsageError for another kind or when neither says). io::InputError when missing,
  /// unreadable or without queries, io::ParseError ("file:line: reason") when malformed. Rigid
  /// files have their truth column: `truth` is not read.
  static Dataset load(const std::string& path, const std::optional<QueryKind>& kind, const TruthSource& truth);
  /// UsageError for a baseline: rigid queries take filtered or exact.
  static void check_method(tools::Method m);
  /// --truth is a UsageError (rigid files have their truth column).
  static TruthSource truth_source(const ParsedOptions& options, std::size_t files, bool answers);
  /// Both methods answer every question: no-op.
  static void require_answers(const Dataset&, tools::Method, const CcdParams&) {}
  /// Query i through the library's one entry point (answer_query of exactccd/rigid.hpp): its TOI
  /// when want_toi, else any enclosure on collision.
  static std::optional<TimeInterval> answer(const Dataset& d, std::size_t i, tools::Method method,
                                            StageCounters* counters, bool want_toi, const CcdParams& params);
  /// answer for queries [begin, end) into out[0, end - begin), one by one.
  static void answer_range(const Dataset& d, std::size_t begin, std::size_t end, tools::Method method,
                           StageCounters& counters, bool want_toi, const CcdParams& params,
                           std::optional<TimeInterval>* out) {
    for (std::size_t i = begin; i < end; ++i) out[i - begin] = answer(d, i, method, &counters, want_toi, params);
  }
  /// check --json's "motion": "rigid".
  static constexpr const char* record_motion = "rigid";
  /// The stages of the rigid filtered method.
  static StageCounts stage_counts(const StageCounters& s);

  /// The bundled data's rigid/ (`data`: bundled_data_dir, data_dir.hpp).
  static std::vector<std::string> bundled_files(const std::filesystem::path& data);
  class BenchCase;
  class BenchTable;

  /// families, sim.
  static const std::vector<GenerateSet>& generate_sets();
};

/// One rigid dataset in bench. Two arms: the rigid filtered method, and the linear filtered
/// method on the same bodies' linearised queries (each vertex's world positions at t0 and t1,
/// rounded to doubles, as a linear query). FP and FN of the rigid method against the truth
/// column at the contact question (unless --methods has exact), else against Method::exact.
class RigidMotion::BenchCase {
 public:
  /// Linearises every query.
  BenchCase(const Dataset& d, const BenchSettings& s);
  /// The dataset.
  const Dataset& dataset() const { return d_; }
  /// The largest extent of the linearised query's bounding box.
  double box_size(std::size_t i) const;
  /// The truth column (at the contact question, unless --methods has exact), else Method::exact.
  std::vector<bool> reference(const std::vector<CcdParams>& params, bool contact_question) const;
  /// The rigid filtered method, then the linear filtered method on the linearised queries.
  std::vector<BenchArm> arms(const std::vector<CcdParams>& params) const;

 private:
  const Dataset& d_;
  const BenchSettings& s_;
  std::vector<std::array<Vec3, 8>> linearised_;  ///< each query's points at t0, then at t1
};

/// bench's table of rigid datasets: one row per (dataset, d) with both arms' times and their ratio.
class RigidMotion::BenchTable {
 public:
  /// --json is a UsageError.
  explicit BenchTable(const BenchSettings& s);
  /// Prints the header.
  void header();
  /// Prints the row of one (dataset, d).
  void add(const BenchCase& c, double distance, const std::vector<bool>& reference, const std::vector<ArmRun>& runs);
  /// Nothing to finish.
  void finish() {}

 private:
  const BenchSettings& s_;
};

}  // namespace exactccd::cli
