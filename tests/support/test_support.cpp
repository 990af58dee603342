#include "support/test_support.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace zraster::test {

std::filesystem::path shared_data(const std::string& relative) {
    return std::filesystem::path(ZRASTER_SHARED_DATA) / relative;
}

bool have_shared_data() {
    return std::filesystem::is_directory(std::filesystem::path(ZRASTER_SHARED_DATA) / "meshes");
}

std::filesystem::path temp_dir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("zraster-test-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

CommandResult run_zraster(const std::string& arguments, const std::filesystem::path& cwd) {
    std::string command;
    if (!cwd.empty()) command = "cd '" + cwd.string() + "' && ";
    command += std::string("'") + ZRASTER_CLI + "' " + arguments + " 2>&1 </dev/null";
    return run_shell_line(command);
}

CommandResult run_shell_line(const std::string& line) {
    FILE* pipe = popen(line.c_str(), "r");
    std::string out;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        out.append(buffer.data(), n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace zraster::test
