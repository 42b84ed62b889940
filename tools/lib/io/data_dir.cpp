// The run-time lookup of the bundled data and the shared sample (data_dir.hpp).
#include "io/data_dir.hpp"

#include <cstdlib>
#include <system_error>
#include <vector>

#include "io/input_file.hpp"

// The folder share/exactccd relative to the program's folder: installed (CMakeLists.txt derives
// it from GNUInstallDirs' bin and data folders: "../share/exactccd" by default), and in a build
// tree, where CMake links share/exactccd/data and share/exactccd/sample-queries beside the
// program. Both are relative paths: the program holds no path of the machine it was built on.
#ifndef EXACTCCD_SHARE_FROM_PROGRAM
#error "EXACTCCD_SHARE_FROM_PROGRAM (the installed share/exactccd relative to bin/) is set by CMakeLists.txt"
#endif
#ifndef EXACTCCD_BUILD_TREE_SHARE
#error "EXACTCCD_BUILD_TREE_SHARE (share/exactccd beside the build tree's program) is set by CMakeLists.txt"
#endif

namespace exactccd::io {
namespace {

namespace fs = std::filesystem;

/// The program's own path (the target of /proc/self/exe), or nullopt where it cannot be read.
std::optional<fs::path> program_path() {
  std::error_code ec;
  fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  return exe;
}

/// The folders share/exactccd can be, relative to the program, in the order they are tried:
/// the installed layout, then a build tree's (empty when the program's path is unknown).
std::vector<fs::path> share_folders() {
  const std::optional<fs::path> exe = program_path();
  if (!exe) return {};
  const fs::path bin = exe->parent_path();
  return {(bin / EXACTCCD_SHARE_FROM_PROGRAM).lexically_normal(), (bin / EXACTCCD_BUILD_TREE_SHARE).lexically_normal()};
}

/// Whether `path` is a folder (false when it cannot be examined).
bool is_folder(const fs::path& path) {
  std::error_code ec;
  return fs::is_directory(path, ec);
}

/// An environment variable's value ("" when unset).
std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

/// `folder` when it is a folder, else an InputError (from `who`) saying that `how` (the option or
/// the environment variable that named it) names none.
fs::path named_folder(const std::string& folder, const std::string& how, const std::string& who) {
  if (is_folder(folder)) return folder;
  throw InputError(who, how + " '" + folder + "' is not a folder (the bundled data: catalogue, families, " +
                            "kinds, rigid, scenes, sim)");
}

/// The error when no data folder was named and none is found relative to the program.
InputError not_found(const std::vector<fs::path>& looked, const std::string& who) {
  std::string where;
  for (const fs::path& p : looked) where += (where.empty() ? "" : " and ") + p.string();
  const std::optional<fs::path> exe = program_path();
  const std::string relative = exe ? "looked in " + where + " (relative to the program " + exe->string() + ")"
                                   : std::string("the program's own location (/proc/self/exe) is unknown");
  return InputError(who, "no FILE given and the bundled data was not found: " + relative +
                              "; name its folder with --data-dir DIR or the environment variable " + kDataDirVariable);
}

}  // namespace

fs::path bundled_data_dir(const std::string& option, const std::string& who) {
  if (!option.empty()) return named_folder(option, "--data-dir", who);
  const std::string variable = environment(kDataDirVariable);
  if (!variable.empty()) return named_folder(variable, std::string("the environment variable ") + kDataDirVariable, who);
  std::vector<fs::path> looked;
  for (const fs::path& share : share_folders()) {
    looked.push_back(share / "data");
    if (is_folder(looked.back())) return looked.back();
  }
  throw not_found(looked, who);
}

std::optional<fs::path> shared_sample_dir() {
  const std::string variable = environment(kSampleDirVariable);
  if (!variable.empty()) return fs::path(variable);
  for (const fs::path& share : share_folders())
    if (is_folder(share / "sample-queries")) return share / "sample-queries";
  return std::nullopt;
}

}  // namespace exactccd::io
