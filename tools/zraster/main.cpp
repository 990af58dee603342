// zraster: the command-line renderer. One file per subcommand; run.cpp dispatches and maps
// failures to exit codes: 0 success, 2 bad input or usage (one line on stderr naming the file or
// option and the cause), 1 internal error.
#include <csignal>
#include <string>
#include <vector>

#include "run.hpp"

int main(int argc, char** argv) {
    // Past a file size limit (ulimit -f) a write fails with EFBIG instead of killing the process:
    // the outputs' usual failure path then reports it and removes the temporaries.
    std::signal(SIGXFSZ, SIG_IGN);
    return zraster::cli::run_zraster(std::vector<std::string>(argv + 1, argv + argc));
}
