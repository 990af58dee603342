// Helpers shared by the test suites: where the shared meshes live, and skipping when they do not.
#pragma once
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace zraster::test {

// Path of a file under ../shared/data (e.g. "meshes/obj/bunny.obj").
std::filesystem::path shared_data(const std::string& relative);

// True when ../shared/data is beside the repository (it is in CI, not in a user's clone).
bool have_shared_data();

// A fresh, empty directory for one test's output files.
std::filesystem::path temp_dir(const std::string& name);

// The whole content of a file (empty when it cannot be read).
inline std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The same elements, bit for bit (NaNs and signed zeros included).
template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// One line of text, ending with its newline: what every error message of the command is.
inline bool single_line(const std::string& s) {
    return !s.empty() && s.find('\n') == s.size() - 1;
}

// Runs the built zraster command with `arguments` (shell syntax) in `cwd`, no standard input.
struct CommandResult {
    int exit_code;
    std::string output;  // stdout and stderr
};
CommandResult run_zraster(const std::string& arguments, const std::filesystem::path& cwd = {});
// Runs a shell command line as it is, its stdout (redirect stderr into it in the line) and exit
// status (-1 when it did not exit normally).
CommandResult run_shell_line(const std::string& line);

}  // namespace zraster::test

// Skips the current test with a clear message when ../shared/data is absent.
#define ZRASTER_REQUIRE_SHARED_DATA()                                                      \
    do {                                                                                   \
        if (!::zraster::test::have_shared_data())                                          \
            GTEST_SKIP() << "../shared/data is absent (a bare clone): skipping this test"; \
    } while (0)
