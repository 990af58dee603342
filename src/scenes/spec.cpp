// Scene specs naming procedural scenes: "sphere:N", "city:N[:SEED]", "soup:N[:SEED]",
// "builtin:NAME".
#include "scenes/building.hpp"
#include "scenes/default_scene.hpp"

#include <zraster/error.hpp>
#include <zraster/scenes.hpp>

#include <charconv>
#include <string>
#include <vector>

namespace zraster {

namespace {

constexpr const char* malformed_message =
    "malformed scene spec: expected sphere:N, city:N[:SEED] or soup:N[:SEED]";

// Past these sizes a scene needs gigabytes; a typo of a few digits should not start that.
constexpr std::uint64_t max_triangles_spec = 20'000'000;  // sphere, soup
constexpr std::uint64_t max_boxes_spec = 2'000'000;       // city: 10 triangles per box

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (;;) {
        const auto at = text.find(separator);
        parts.push_back(text.substr(0, at));
        if (at == std::string_view::npos) return parts;
        text.remove_prefix(at + 1);
    }
}

enum class ParseResult { Ok, Malformed, OutOfRange };

// Decimal digits only: no sign, no spaces, no trailing characters.
ParseResult parse_unsigned(std::string_view text, std::uint64_t& value) {
    if (text.empty()) return ParseResult::Malformed;
    for (const char c : text)
        if (c < '0' || c > '9') return ParseResult::Malformed;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range) return ParseResult::OutOfRange;
    if (error != std::errc() || end != text.data() + text.size()) return ParseResult::Malformed;
    return ParseResult::Ok;
}

bool has_prefix(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

Scene single_mesh_scene(Mesh mesh, std::string_view spec) {
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(mesh));
    Scene scene = scene_from_meshes(std::move(meshes));
    scene.name = std::string(spec);
    return scene;
}

Scene make_builtin_scene(std::string_view spec) {
    const std::string_view name = spec.substr(std::string_view("builtin:").size());
    if (name == "default") {
        Scene scene = make_default_scene();
        scene.name = std::string(spec);
        return scene;
    }
    if (name == "sphere") return single_mesh_scene(make_uv_sphere(1.0f, 64, 128), spec);
    if (name == "cube") return single_mesh_scene(make_box(glm::vec3(1.0f)), spec);
    throw InputError(std::string(spec),
                     "unknown builtin scene: expected builtin:default, builtin:sphere or "
                     "builtin:cube");
}

}  // namespace

// A prefix is enough: "sphere:abc" is a malformed spec to report as such, not a file to look for.
bool is_procedural_spec(std::string_view spec) {
    return has_prefix(spec, "sphere:") || has_prefix(spec, "city:") || has_prefix(spec, "soup:") ||
           has_prefix(spec, "builtin:") || has_prefix(spec, "building:");
}

Scene make_procedural_scene(std::string_view spec) {
    if (has_prefix(spec, "builtin:")) return make_builtin_scene(spec);
    if (const auto building = detail::parse_building_spec(spec)) {
        Scene scene = make_building(building->rows, building->columns, building->seed);
        scene.name = std::string(spec);
        return scene;
    }

    const std::string file(spec);
    const auto parts = split(spec, ':');
    const std::string_view kind = parts[0];
    const bool seeded = kind == "city" || kind == "soup";
    if ((kind != "sphere" && !seeded) || parts.size() < 2 || parts.size() > (seeded ? 3u : 2u))
        throw InputError(file, malformed_message);

    const std::uint64_t limit = kind == "city" ? max_boxes_spec : max_triangles_spec;
    std::uint64_t n = 0;
    const ParseResult parsed = parse_unsigned(parts[1], n);
    if (parsed == ParseResult::Malformed) throw InputError(file, malformed_message);
    if (parsed == ParseResult::OutOfRange || n < 1 || n > limit)
        throw InputError(file, "N out of range (1.." + std::to_string(limit) + ")");

    std::uint64_t seed = 1;
    if (parts.size() == 3) {
        const ParseResult seed_parsed = parse_unsigned(parts[2], seed);
        if (seed_parsed == ParseResult::OutOfRange)
            throw InputError(file, "SEED out of range (0..18446744073709551615)");
        if (seed_parsed != ParseResult::Ok) throw InputError(file, malformed_message);
    }

    if (kind == "sphere") return single_mesh_scene(make_bench_sphere(long(n)), spec);
    if (kind == "city") return single_mesh_scene(make_bench_city(long(n), seed), spec);
    return single_mesh_scene(make_bench_soup(long(n), seed), spec);
}

}  // namespace zraster
