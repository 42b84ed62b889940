// Where the program finds the data it ships (the repository's data/, installed as
// <prefix>/share/exactccd/data) and the shared benchmark sample, at run time: an option, an
// environment variable, else relative to the program's own location; never a path compiled in,
// so that an installed program needs no checkout (docs/cli.md, "Where the program finds its
// data").
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace exactccd::io {

/// The environment variable naming the bundled data folder (after --data-dir, before the
/// program's own location).
inline constexpr const char* kDataDirVariable = "EXACTCCD_DATA_DIR";
/// The environment variable naming the shared benchmark sample (the folder holding unit-tests/).
inline constexpr const char* kSampleDirVariable = "EXACTCCD_SAMPLE_QUERIES_DIR";

/// The bundled data folder (catalogue, families, kinds, rigid, scenes, sim), in this order:
/// `option` (--data-dir) when not empty; else the environment variable EXACTCCD_DATA_DIR when
/// set and not empty; else share/exactccd/data relative to the program's own folder (its
/// /proc/self/exe): <bin>/../share/exactccd/data when installed, <build>/share/exactccd/data in
/// a build tree (a link CMake makes to the checkout's data/). The first of these given is the
/// only one tried. Throws InputError (the program's exit 2), its message starting with `who`
/// ("bench"), when
/// the folder named is none, or when none was named and none is found relative to the program:
/// the message names every place looked at, --data-dir and EXACTCCD_DATA_DIR.
std::filesystem::path bundled_data_dir(const std::string& option, const std::string& who);

/// The shared benchmark sample's folder (bench without files starts with its unit-tests):
/// EXACTCCD_SAMPLE_QUERIES_DIR when set and not empty, else share/exactccd/sample-queries
/// relative to the program when it exists (a build tree's link to the CMake cache variable
/// EXACTCCD_SAMPLE_QUERIES_DIR; an installation has none). nullopt: no sample.
std::optional<std::filesystem::path> shared_sample_dir();

}  // namespace exactccd::io
