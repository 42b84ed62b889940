// The ground truth of the Scalable CCD dataset (its mma_bool/*.json files): a JSON array of
// booleans, one per query in file order. Strict: anything else is an error naming the line.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "io/benchmark_csv.hpp"  // ParseError

namespace exactccd::io {

/// Parses a JSON array of booleans (`[true, false, ...]`, any JSON whitespace, a UTF-8 byte
/// order mark skipped). Throws ParseError ("<source>:<line>: reason") on anything else: another
/// value (numbers, strings, null, nested arrays), a missing or extra comma or bracket, data
/// after the array, an empty input.
std::vector<bool> read_truth_json(std::istream& in, const std::string& source_name);

/// read_truth_json on the file at `path` (InputError when it cannot be opened).
std::vector<bool> read_truth_json_file(const std::string& path);

}  // namespace exactccd::io
