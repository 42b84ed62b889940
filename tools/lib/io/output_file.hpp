// Output files of the tools (the exactccd subcommands, sharded runs' partials): checked for writability before the work starts,
// written to a temporary in the same directory and renamed into place, so that no run leaves
// a half-written file behind. Every failure is a UsageError naming the path (exit code 2).
#pragma once

#include <fstream>
#include <ostream>
#include <string>

namespace exactccd::io {

/// A file written through a temporary ("<path>.tmp.<pid>.<n>") renamed over `path` by commit().
/// Until then `path` is untouched; a file not committed (an error, an exception) leaves no
/// temporary behind.
class AtomicOutputFile {
 public:
  /// Creates the temporary. Throws UsageError "<path>: is a directory" or "<path>: cannot
  /// write: <system reason>" (a missing or unwritable directory, ...).
  explicit AtomicOutputFile(const std::string& path);
  /// Removes the temporary unless committed.
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  /// Where to write.
  std::ostream& stream() { return out_; }
  /// Flushes, closes and renames the temporary to the path. Throws UsageError "<path>: write
  /// error" or "<path>: cannot write: <reason>" (the path then keeps its old content).
  void commit();

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `text` to `path` through an AtomicOutputFile.
void write_file_atomically(const std::string& path, const std::string& text);

/// Makes `path` a directory files can be written in: creates it (and its parents) when missing,
/// then creates and removes a probe file in it. Throws UsageError "<path>: not a directory",
/// "<path>: cannot create directory: <reason>" or "<path>: cannot write: <reason>".
void prepare_output_directory(const std::string& path);

}  // namespace exactccd::io
