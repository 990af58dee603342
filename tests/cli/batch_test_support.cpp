#include "batch_test_support.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numbers>

namespace zraster::test {

void write_sphere_obj(const std::filesystem::path& path, int segments, int seed) {
    const int stacks = std::max(2, segments / 2), slices = std::max(3, segments);
    const double squash = 0.6 + 0.1 * (seed % 5), turn = 0.37 * seed;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path);
    out << "# test sphere " << seed << "\n";
    out << "v 0 1 0\n";
    for (int i = 1; i < stacks; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / slices + turn;
            out << "v " << std::sin(theta) * std::cos(phi) << " " << squash * std::cos(theta) << " "
                << -std::sin(theta) * std::sin(phi) << "\n";
        }
    }
    out << "v 0 " << -squash << " 0\n";
    const auto ring = [&](int i, int j) { return 2 + (i - 1) * slices + (j % slices); };
    for (int j = 0; j < slices; ++j) out << "f 1 " << ring(1, j) << " " << ring(1, j + 1) << "\n";
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j)
            out << "f " << ring(i, j) << " " << ring(i + 1, j) << " " << ring(i + 1, j + 1) << " "
                << ring(i, j + 1) << "\n";
    const int bottom = 2 + (stacks - 1) * slices;
    for (int j = 0; j < slices; ++j)
        out << "f " << ring(stacks - 1, j) << " " << bottom << " " << ring(stacks - 1, j + 1)
            << "\n";
}

void write_box_stl(const std::filesystem::path& path, int seed) {
    const float s = 0.5f + 0.1f * float(seed % 7);
    const float c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
    std::string bytes(80, ' ');
    const std::uint32_t count = 12;
    bytes.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& f : faces) {
        const float normal[3] = {0, 0, 0};
        bytes.append(reinterpret_cast<const char*>(normal), 12);
        for (const int v : f) {
            const float p[3] = {c[v][0] * s, c[v][1], c[v][2] * (2.0f - s)};
            bytes.append(reinterpret_cast<const char*>(p), 12);
        }
        bytes.append(2, '\0');
    }
    write_text(path, bytes);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<nlohmann::json> read_log(const std::filesystem::path& path) {
    std::vector<nlohmann::json> records;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) records.push_back(nlohmann::json::parse(line));
    return records;
}

std::map<std::string, nlohmann::json> records_by_input(const std::vector<nlohmann::json>& log) {
    std::map<std::string, nlohmann::json> last;
    for (const nlohmann::json& record : log) last[record.at("input").get<std::string>()] = record;
    return last;
}

std::set<std::string> files_under(const std::filesystem::path& dir) {
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file())
            files.insert(entry.path().lexically_relative(dir).generic_string());
    return files;
}

CommandResult run_shell(const std::string& command, const std::filesystem::path& cwd) {
    return run_shell_line("cd '" + cwd.string() + "' && { " + command + " ; } 2>&1");
}

std::string zraster_command() {
    return std::string("'") + ZRASTER_CLI + "'";
}

}  // namespace zraster::test
