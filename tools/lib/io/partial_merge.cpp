// Writing and merging the partial results of sharded runs (partial_merge.hpp).
#include "io/partial_merge.hpp"

#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "io/input_file.hpp"  // UsageError
#include "io/output_file.hpp"

namespace exactccd::io {

void write_partial(const std::string& path, const Partial& p) {
  io::AtomicOutputFile file(path);
  std::ostream& out = file.stream();
  out << kPartialMagic << "\ncommand " << p.command << "\n";
  for (const auto& [key, value] : p.settings) {
    if (key.empty() || key.find_first_of(" \n") != std::string::npos || value.find('\n') != std::string::npos)
      throw UsageError(path + ": cannot record the setting '" + key + "' (a line break in a name or path)");
    out << "setting " << key << " " << value << "\n";
  }
  out << "shard " << p.shard_index << " " << p.shard_count << "\n";
  out << "range " << p.begin << " " << p.end << " " << p.total << "\n";
  for (const PartialRecord& r : p.records) out << r.text << "\n";
  out << "end " << p.records.size() << "\n";
  file.commit();
}

Partial merge_partials(const std::vector<std::string>& paths) {
  if (paths.empty()) throw UsageError("merge: no partial file (see exactccd merge --help)");
  std::vector<Partial> parts;
  for (const std::string& path : paths) parts.push_back(read_partial(path));
  const Partial& first = parts.front();
  // Shard index -> file: sparse, so that memory follows the files given, not the files' N.
  std::map<std::size_t, std::size_t> by_shard;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Partial& p = parts[i];
    const std::string& path = paths[i];
    if (p.command != first.command)
      throw UsageError("merge: " + path + " is from '" + p.command + "' but " + paths[0] + " from '" +
                       first.command + "'");
    if (p.settings != first.settings)
      throw UsageError("merge: " + path + " and " + paths[0] + " are from runs with different settings");
    if (p.shard_count != first.shard_count || p.total != first.total)
      throw UsageError("merge: " + path + " is shard " + std::to_string(p.shard_index) + " of " +
                       std::to_string(p.shard_count) + " over " + std::to_string(p.total) + " queries, " + paths[0] +
                       " of " + std::to_string(first.shard_count) + " over " + std::to_string(first.total));
    if (const auto seen = by_shard.find(p.shard_index); seen != by_shard.end())
      throw UsageError("merge: shard " + std::to_string(p.shard_index) + " given twice (" + paths[seen->second] +
                       " and " + path + ")");
    const std::size_t begin = p.total * p.shard_index / p.shard_count;
    const std::size_t end = p.total * (p.shard_index + 1) / p.shard_count;
    if (p.begin != begin || p.end != end)
      throw UsageError("merge: " + path + " covers queries [" + std::to_string(p.begin) + ", " + std::to_string(p.end) +
                       "), not [" + std::to_string(begin) + ", " + std::to_string(end) + ") of shard " +
                       std::to_string(p.shard_index) + "/" + std::to_string(p.shard_count));
    by_shard[p.shard_index] = i;
  }
  if (by_shard.size() != first.shard_count) {
    // The first ten missing shards, and how many there are in all.
    std::string missing;
    std::size_t listed = 0;
    for (std::size_t s = 0; s < first.shard_count && listed < 10; ++s)
      if (by_shard.count(s) == 0) missing += (listed++ == 0 ? "" : ", ") + std::to_string(s);
    const std::size_t count = first.shard_count - by_shard.size();
    if (count > listed) missing += ", ... (" + std::to_string(count) + " in all)";
    throw UsageError("merge: missing shards (of " + std::to_string(first.shard_count) + "): " + missing);
  }
  Partial merged;
  merged.command = first.command;
  merged.settings = first.settings;
  merged.shard_index = 0;
  merged.shard_count = 1;
  merged.begin = 0;
  merged.end = merged.total = first.total;
  for (const auto& [shard, i] : by_shard)  // in shard order
    for (PartialRecord& r : parts[i].records) merged.records.push_back(std::move(r));
  return merged;
}

}  // namespace exactccd::io
