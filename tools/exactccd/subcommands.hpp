// The subcommands of the exactccd program. Each takes the arguments after its name and returns
// an exit code (cli_common.hpp); it may throw UsageError or io::ParseError.
#pragma once

namespace exactccd::cli {

int run_check(int argc, char** argv);
int run_bench(int argc, char** argv);
int run_generate(int argc, char** argv);
int run_stability(int argc, char** argv);
int run_compare(int argc, char** argv);

}  // namespace exactccd::cli
