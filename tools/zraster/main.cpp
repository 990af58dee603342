// zraster: the command-line renderer. One file per subcommand; run.cpp dispatches and maps
// failures to exit codes: 0 success, 2 bad input or usage (one line on stderr naming the file or
// option and the cause), 1 internal error.
#include <string>
#include <vector>

#include "run.hpp"

int main(int argc, char** argv) {
    return zraster::cli::run_zraster(std::vector<std::string>(argv + 1, argv + argc));
}
