// exactccd: the command-line program. Dispatches to one subcommand per file.
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "cli_common.hpp"
#include "exactccd/exactccd.h"
#include "io/input_file.hpp"
#include "numeric/simd_level.hpp"
#include "subcommands.hpp"

namespace {

struct Subcommand {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

constexpr Subcommand kSubcommands[] = {
    {"check", exactccd::cli::run_check, "answer benchmark CSV queries and compare with their truth"},
    {"bench", exactccd::cli::run_bench, "time every method on the same queries; FP/FN; filter stages"},
    {"generate", exactccd::cli::run_generate, "write the project's query sets (catalogue, sim, families)"},
    {"compare", exactccd::cli::run_compare, "another code's answers against the exact ones, by category"},
    {"stability", exactccd::cli::run_stability, "error rates of every method on the degenerate families vs k"},
    {"scene", exactccd::cli::run_scene, "exact CCD of a whole mesh over one step (two OBJ files)"},
    {"fuzz-against", exactccd::cli::run_fuzz_against, "another code (a plug-in .so) against the exact answers"},
    {"merge", exactccd::cli::run_merge, "the report of a sharded compare or fuzz-against run from its partial files"},
};

void print_help() {
  std::cout << "usage: exactccd <subcommand> [options]\n\n"
               "Exact continuous collision detection (vertex-face and edge-edge).\n\nsubcommands:\n";
  for (const Subcommand& s : kSubcommands) std::cout << "  " << s.name << "\t" << s.summary << "\n";
  std::cout << "\n  exactccd <subcommand> --help   options of one subcommand\n"
               "  exactccd --version             the version\n\n"
               "exit codes: 0 ran, 1 internal error, 2 bad usage or malformed input.\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace exactccd::cli;
  if (argc < 2) {
    print_help();
    return kExitUsage;
  }
  const std::string first = argv[1];
  if (first == "-h" || first == "--help" || first == "help") {
    print_help();
    return kExitOk;
  }
  if (first == "--version") {
    std::cout << "exactccd " << exactccd_version() << "\n";  // the library's: one version (CMake's)
    std::cout << "simd: " << exactccd::numeric::simd_level_text() << "\n";  // the batched stages' level
    return kExitOk;
  }
  for (const Subcommand& s : kSubcommands) {
    if (first != s.name) continue;
    try {
      const int code = s.run(argc - 2, argv + 2);
      // Output that could not be written (a full disk, a closed pipe) is no silent success.
      std::cout.flush();
      if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
        std::cerr << "exactccd: cannot write the standard output\n";
        return kExitUsage;
      }
      return code;
    } catch (const UsageError& e) {
      std::cerr << "exactccd: " << e.what() << "\n";
      return kExitUsage;
    } catch (const exactccd::io::InputError& e) {  // ParseError included: file:line: reason
      std::cerr << "exactccd: " << e.what() << "\n";
      return kExitUsage;
    } catch (const std::exception& e) {
      std::cerr << "exactccd: internal error: " << e.what() << "\n";
      return kExitInternal;
    }
  }
  std::cerr << "exactccd: unknown subcommand '" << first << "' (see exactccd --help)\n";
  return kExitUsage;
}
