// Helpers of the `zraster batch` tests: small mesh files written into a test's folder, good and
// broken; the batch log read back; files compared byte for byte.
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace zraster::test {

// A closed UV sphere as OBJ (v and f lines), `segments` around (at least 3), squashed and turned
// by `seed` so that every seed gives a different picture.
void write_sphere_obj(const std::filesystem::path& path, int segments, int seed);
// A box as binary STL, its size set by `seed`.
void write_box_stl(const std::filesystem::path& path, int seed);
void write_text(const std::filesystem::path& path, const std::string& text);

// The records of a batch log, in file order.
std::vector<nlohmann::json> read_log(const std::filesystem::path& path);
// The last record of each input.
std::map<std::string, nlohmann::json> records_by_input(const std::vector<nlohmann::json>& log);

// Every regular file under `dir`, as paths relative to it ('/'-separated), sorted.
std::set<std::string> files_under(const std::filesystem::path& dir);

// Runs a shell command line in `cwd` (stdout and stderr together).
CommandResult run_shell(const std::string& command, const std::filesystem::path& cwd);
// The built zraster command, quoted for the shell.
std::string zraster_command();

}  // namespace zraster::test
