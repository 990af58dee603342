#include "io/lightwave_scene_check.hpp"

#include <zraster/error.hpp>

#include "io/obj_parser.hpp"
#include "io/reference_policy.hpp"
#include "io/text_util.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <system_error>

namespace zraster::io {

namespace {

// The object path of a LoadObjectLayer (after its layer number) or LoadObject line, "" else.
std::string lws_object_path(std::string_view line) {
    line = trim(line);
    bool layer = false;
    if (line.starts_with("LoadObjectLayer")) {
        layer = true;
        line.remove_prefix(15);
    } else if (line.starts_with("LoadObject")) {
        line.remove_prefix(10);
    } else {
        return {};
    }
    if (line.empty() || !std::isspace(static_cast<unsigned char>(line[0]))) return {};
    line = trim(line);
    if (layer) {
        std::size_t i = 0;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        line = trim(line.substr(i));
    }
    if (line.size() >= 2 && line.front() == '"' && line.back() == '"')
        line = line.substr(1, line.size() - 2);
    return std::string(line);
}

bool is_lightwave_scene(const std::filesystem::path& object) {
    std::string extension = object.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".lws") return true;
    std::ifstream in(object, std::ios::binary);
    char head[4] = {};
    in.read(head, sizeof head);
    return in.gcount() == 4 && std::string_view(head, 4) == "LWSC";
}

// An object is read as the file it is, with the checks it would have if it were given directly
// (the budgets of its format); a scene among the objects is refused (Assimp read one loading
// itself until its stack overflowed, and two loading each other until stopped).
void check_object(const std::filesystem::path& object, const std::string& name,
                  const std::string& file, const LoadOptions& options) {
    if (is_lightwave_scene(object))
        throw InputError(file, "its object '" + name +
                                   "' is a LightWave scene: a scene loads objects, not scenes");
    const auto in_scene = [&](const InputError& e) {
        return "its object '" + name + "': " + e.cause();
    };
    try {
        (void)precheck_assimp_input(object, options);
    } catch (const LimitExceeded& e) {
        throw LimitExceeded(file, e.limit(), in_scene(e));
    } catch (const InputError& e) {
        throw InputError(file, in_scene(e));
    }
}

}  // namespace

void check_lightwave_scene(const std::filesystem::path& path, const LoadOptions& options) {
    const std::string file = path.string();
    const ReferencePolicy policy(path, options.allow_outside_references);
    std::ifstream in(path, std::ios::binary);
    std::string line;
    std::map<std::string, std::uintmax_t> sizes;  // readable objects
    std::uint64_t loads = 0;
    long double object_bytes = 0;
    const std::uint64_t max_loads =
        std::max<std::uint64_t>(1, options.max_instances / kLightWaveLoadWeight);
    while (std::getline(in, line)) {
        const std::string name = lws_object_path(line);
        if (name.empty()) continue;
        auto it = sizes.find(name);
        if (it == sizes.end()) {
            const std::filesystem::path object = std::filesystem::path(name).is_absolute()
                                                     ? std::filesystem::path(name)
                                                     : path.parent_path() / name;
            const ReferencePolicy::Check check = policy.check(object);
            if (check.verdict == ReferencePolicy::Verdict::Refused)
                throw InputError(file, "its object '" + name + "' " + check.reason + ": refused" +
                                           check.advice());
            std::uintmax_t size = 0;
            if (check.verdict == ReferencePolicy::Verdict::Readable) {
                std::error_code ec;
                size = std::filesystem::file_size(object, ec);
                if (ec) size = 0;
                if (size > options.max_file_bytes)
                    throw LimitExceeded(file, "max_file_bytes",
                                        "its object '" + name + "' is " + std::to_string(size) +
                                            " bytes, more than max_file_bytes (" +
                                            std::to_string(options.max_file_bytes) + ")");
                check_object(object, name, file, options);
            }
            it = sizes.emplace(name, size).first;
        }
        ++loads;
        object_bytes += static_cast<long double>(it->second);
    }
    if (loads > max_loads)
        throw LimitExceeded(file, "max_instances",
                            "it loads objects " + std::to_string(loads) + " times, more than " +
                                std::to_string(max_loads) + " (max_instances / " +
                                std::to_string(kLightWaveLoadWeight) +
                                ": the importer combines the loads in time quadratic in their "
                                "number)");
    const long double bytes = object_bytes * kLightWaveBytesPerObjectByte;
    if (bytes > static_cast<long double>(options.max_geometry_bytes))
        throw LimitExceeded(file, "max_geometry_bytes",
                            "its " + std::to_string(loads) + " object loads read " +
                                std::to_string(static_cast<std::uint64_t>(object_bytes)) +
                                " bytes of objects, about " +
                                std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20))) +
                                " MiB once imported, more than max_geometry_bytes (" +
                                std::to_string(options.max_geometry_bytes >> 20) + " MiB)");
}

}  // namespace zraster::io
