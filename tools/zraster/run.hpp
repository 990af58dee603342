// The zraster command as a function: what main() does, callable with any argument vector (the
// CLI fuzzer calls it in-process, fuzz/fuzz_cli.cpp).
#pragma once
#include <string>
#include <vector>

namespace zraster::cli {

// Parses `args` (the command line without the program name), runs the subcommand and returns
// the exit status: 0 success, 2 bad input or usage (one line on stderr naming the file or option
// and the cause, no output file left behind), 1 internal error.
int run_zraster(std::vector<std::string> args);

}  // namespace zraster::cli
