// Partial results of a sharded run (`--shard I/N --partial FILE`), as `exactccd merge` reads them
// (the writing and the merge are the command line's: tools/exactccd/partial.hpp).
//
// File format (text, one record per line):
//   exactccd-partial 1
//   command NAME                  compare | fuzz-against
//   setting KEY VALUE             the run's settings; every shard of a run has the same
//   shard I N
//   range BEGIN END TOTAL         the global query indices [BEGIN, END) of [0, TOTAL)
//   ...records...                 command-specific (compare.cpp, fuzz_against.cpp)
//   end COUNT                     the number of records: a truncated file is an error
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace exactccd::io {

/// The first line of a partial file.
constexpr const char* kPartialMagic = "exactccd-partial 1";

/// The largest N of a shard I/N (the command line's --shard limit, cli::kMaxShards).
constexpr std::size_t kMaxPartialShards = 1000000;

/// A command-specific line of a partial, with where it was read (for error messages).
struct PartialRecord {
  std::string text;
  std::string source;    ///< the file it was read from ("" when built in memory)
  std::size_t line = 0;  ///< its line there
};

/// One shard's partial results.
struct Partial {
  std::string command;                                     ///< the subcommand that wrote it
  std::vector<std::pair<std::string, std::string>> settings;  ///< (key, value) in order
  std::size_t shard_index = 0, shard_count = 1;
  std::size_t begin = 0, end = 0, total = 0;               ///< [begin, end) of [0, total)
  std::vector<PartialRecord> records;                      ///< command-specific lines

  /// Appends a record built in memory.
  void add(std::string text) { records.push_back({std::move(text), "", 0}); }

  /// The value of setting `key`; throws io::ParseError naming `source` when it is missing.
  const std::string& setting(const std::string& key, const std::string& source) const;
};

/// Reads a partial file. Throws io::InputError / io::ParseError ("<path>:<line>: <reason>") on
/// an unreadable, malformed or truncated file.
Partial read_partial(const std::string& path);

/// x as a hex float ("%a"): reads back as the same double.
std::string hex_double(double x);

/// Parses a hex float written by hex_double (or any finite decimal); throws io::ParseError
/// naming `source` and `line` when `text` is not a finite double.
double parse_double(const std::string& text, const std::string& source, std::size_t line);

/// Parses a non-negative integer; throws io::ParseError naming `source` and `line` otherwise.
std::size_t parse_count(const std::string& text, const std::string& source, std::size_t line);

/// Parses an int (optionally negative); throws io::ParseError naming `source` and `line` otherwise.
int parse_int(const std::string& text, const std::string& source, std::size_t line);

}  // namespace exactccd::io
