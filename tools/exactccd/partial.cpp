#include "partial.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "cli_common.hpp"
#include "io/benchmark_csv.hpp"
#include "io/input_file.hpp"
#include "output_file.hpp"

namespace exactccd::cli {
namespace {

constexpr const char* kMagic = "exactccd-partial 1";

/// The text after the first word of `line` and one space ("" when there is none).
std::string rest_after_word(const std::string& line) {
  const std::size_t space = line.find(' ');
  return space == std::string::npos ? std::string() : line.substr(space + 1);
}

std::string first_word(const std::string& line) { return line.substr(0, line.find(' ')); }

}  // namespace

const std::string& Partial::setting(const std::string& key, const std::string& source) const {
  for (const auto& [k, v] : settings)
    if (k == key) return v;
  throw io::ParseError(source, 1, "no setting '" + key + "' in this partial file");
}

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string hex_double(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

double parse_double(const std::string& text, const std::string& source, std::size_t line) {
  // strtod reads hex floats exactly (C99); from_chars's hex form takes no "0x" prefix.
  const char* begin = text.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || !std::isfinite(x))
    throw io::ParseError(source, line, "'" + text + "' is not a finite number");
  return x;
}

std::size_t parse_count(const std::string& text, const std::string& source, std::size_t line) {
  std::size_t n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw io::ParseError(source, line, "'" + text + "' is not a non-negative integer");
  return n;
}

int parse_int(const std::string& text, const std::string& source, std::size_t line) {
  int v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw io::ParseError(source, line, "'" + text + "' is not an integer");
  return v;
}

void write_partial(const std::string& path, const Partial& p) {
  AtomicOutputFile file(path);
  std::ostream& out = file.stream();
  out << kMagic << "\ncommand " << p.command << "\n";
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

Partial read_partial(const std::string& path) {
  io::InputFile file(path);
  Partial p;
  std::string line;
  std::size_t n = 0;
  const auto next = [&](const char* what) {
    if (!std::getline(file.stream(), line)) {
      file.check_read();
      throw io::ParseError(path, std::max<std::size_t>(n, 1), std::string("unexpected end of file, expected ") + what +
                                            " (a truncated partial file?)");
    }
    ++n;
  };
  next("the header 'exactccd-partial 1'");
  if (line != kMagic) throw io::ParseError(path, n, "not an exactccd partial file (expected 'exactccd-partial 1')");
  next("'command NAME'");
  if (first_word(line) != "command" || rest_after_word(line).empty())
    throw io::ParseError(path, n, "expected 'command NAME'");
  p.command = rest_after_word(line);
  for (;;) {
    next("'setting KEY VALUE' or 'shard I N'");
    if (first_word(line) != "setting") break;
    const std::string kv = rest_after_word(line);
    const std::size_t space = kv.find(' ');
    if (kv.empty() || space == 0) throw io::ParseError(path, n, "expected 'setting KEY VALUE'");
    p.settings.emplace_back(kv.substr(0, space), space == std::string::npos ? "" : kv.substr(space + 1));
  }
  std::vector<std::string> w = split_words(line);
  if (w.size() != 3 || w[0] != "shard") throw io::ParseError(path, n, "expected 'shard I N'");
  p.shard_index = parse_count(w[1], path, n);
  p.shard_count = parse_count(w[2], path, n);
  if (p.shard_count == 0 || p.shard_index >= p.shard_count || p.shard_count > static_cast<std::size_t>(kMaxShards))
    throw io::ParseError(path, n, "shard " + w[1] + " of " + w[2] + ": expected 0 <= I < N <= " + std::to_string(kMaxShards));
  next("'range BEGIN END TOTAL'");
  w = split_words(line);
  if (w.size() != 4 || w[0] != "range") throw io::ParseError(path, n, "expected 'range BEGIN END TOTAL'");
  p.begin = parse_count(w[1], path, n);
  p.end = parse_count(w[2], path, n);
  p.total = parse_count(w[3], path, n);
  // TOTAL bounded so that merge_partials' TOTAL * N (the shards' ranges) cannot wrap around.
  if (p.begin > p.end || p.end > p.total || p.total > std::numeric_limits<std::size_t>::max() / kMaxShards)
    throw io::ParseError(path, n, "range: expected BEGIN <= END <= TOTAL <= " +
                                      std::to_string(std::numeric_limits<std::size_t>::max() / kMaxShards));
  for (;;) {
    next("a record or 'end COUNT'");
    if (first_word(line) == "end") break;
    p.records.push_back({line, path, n});
  }
  w = split_words(line);
  if (w.size() != 2 || parse_count(w[1], path, n) != p.records.size())
    throw io::ParseError(path, n, "'end " + (w.size() > 1 ? w[1] : std::string()) + "' does not match the " +
                                      std::to_string(p.records.size()) + " records read");
  while (std::getline(file.stream(), line)) {
    ++n;
    if (!line.empty()) throw io::ParseError(path, n, "text after 'end'");
  }
  file.check_read();
  return p;
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

}  // namespace exactccd::cli
