// The subcommands of the exactccd program. Each takes the arguments after its name and returns
// an exit code (cli_common.hpp); it may throw UsageError or io::ParseError.
#pragma once

#include <cstdint>
#include <string>

namespace exactccd::io {
struct Partial;
}

namespace exactccd::cli {

int run_check(int argc, char** argv);
int run_bench(int argc, char** argv);
int run_generate(int argc, char** argv);
int run_stability(int argc, char** argv);
int run_compare(int argc, char** argv);
int run_scene(int argc, char** argv);
int run_fuzz_against(int argc, char** argv);
int run_merge(int argc, char** argv);

/// `exactccd merge` of compare partials (compare.cpp): prints the whole run's report.
int merge_compare(const io::Partial& merged, const std::string& source);
/// `exactccd merge --out DIR` of fuzz-against partials (fuzz_against.cpp): prints the report and
/// writes DIR as the whole run does.
int merge_fuzz_against(const io::Partial& merged, const std::string& source, const std::string& out_dir);

/// `exactccd generate scene` (scene.cpp): writes DIR/T0.obj and DIR/T1.obj of a procedural scene.
int generate_scene(const std::string& scene, int resolution, std::uint64_t seed, const std::string& out);

}  // namespace exactccd::cli
