#include "command_line.hpp"

#include "command_caps.hpp"

#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <thread>
#include <utility>
#include <vector>

namespace zraster::cli {
namespace {

std::vector<double> parse_numbers(const std::string& option, const std::string& text,
                                  std::size_t count, const char* shape) {
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string piece = text.substr(start, comma - start);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(piece.data(), piece.data() + piece.size(), v);
        if (piece.empty() || ec != std::errc() || end != piece.data() + piece.size())
            throw InputError(option, "expected " + std::string(shape) + ", got '" + text + "'");
        if (!std::isfinite(v))
            throw InputError(option, "values must be finite, got '" + text + "'");
        values.push_back(v);
        start = comma + 1;
    }
    if (values.size() != count)
        throw InputError(option, "expected " + std::string(shape) + ", got '" + text + "'");
    return values;
}

}  // namespace

std::string exact_number(double x) {
    return fmt::format("{:.17g}", x + 0.0);
}

std::string limit_advice(const std::string& limit) {
    static const std::pair<const char*, const char*> kFlags[] = {
        {"max_painter_comparisons", "--max-painter-comparisons"},
        {"max_bsp_polygons", "--max-bsp-polygons"},
        {"max_warnock_classifications", "--max-warnock-classifications"},
        {"max_abuffer_fragments", "--max-abuffer-fragments"},
        {"max_bsp_classifications", "--max-bsp-classifications"},
        {"max_projected_polygons", "--max-projected-polygons"},
        {"max_painted_fragments", "--max-painted-fragments"},
        {"max_pixels", "--max-pixels"},
        {"max_bin_bytes", "--max-bin-bytes"},
        {"max_explain_pixels", "--max-explain-pixels"},
        {"max_covered_samples", "--max-covered-samples"},
        {"max_instances", "--max-instances"},
        {"max_materials", "--max-materials"},
        {"max_triangles", "--max-triangles"},
        {"max_memory", "--max-memory"},
        {"max_triangulation_work", "--max-triangulation-work"},
        {"worker_timeout_seconds", "--max-load-seconds"},
    };
    static const std::pair<const char*, const char*> kSizeFlags[] = {
        {"max_geometry_bytes", "--max-geometry-memory"},
        {"max_frame_bytes", "--max-frame-bytes"},
        // Set by batch only (its per-job memory).
        {"worker_memory_bytes", "--max-memory"},
    };
    for (const auto& [name, flag] : kFlags)
        if (limit == name) return fmt::format("; raise it with {} N", flag);
    for (const auto& [name, flag] : kSizeFlags)
        if (limit == name)
            return fmt::format("; raise it with {} SIZE (bytes, or with a unit: 512M, 16G)", flag);
    return "";
}

std::uint64_t parse_byte_size(const std::string& option, const std::string& text) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string unit(end, text.data() + text.size());
    for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    int shift = -1;
    if (ec == std::errc() && end != text.data()) {
        const char* const units[] = {"", "k", "m", "g", "t"};
        for (int i = 0; i < 5; ++i)
            for (const std::string tail : {"", "b", "ib"})
                if (unit == units[i] + tail && (i > 0 || tail != "ib")) shift = 10 * i;
    }
    if (shift < 0)
        throw InputError(option,
                         "expected a size in bytes like 4G, 512M or 1000000, got '" + text + "'");
    if (value == 0) throw InputError(option, "must be more than 0 bytes");
    if (value > (~std::uint64_t{0} >> shift))
        throw InputError(option, "'" + text + "' is more than 2^64 bytes");
    return value << shift;
}

void check_instanced_vertices(const Scene& scene, std::uint64_t max_frame_bytes) {
    const std::uint64_t limit = RenderLimits{}.max_vertices;
    if (scene.vertex_count() > limit)
        throw LimitExceeded(scene.name, "max_vertices",
                            std::to_string(scene.vertex_count()) +
                                " vertices over all instances (the meshes times their "
                                "placements), more than the renderer's limit of " +
                                std::to_string(limit));
    check_frame_memory(scene.name, scene.vertex_count(), scene.triangle_count(), 0,
                       RenderLimits{.max_frame_bytes = max_frame_bytes});
}

glm::dvec3 parse_vec3(const std::string& option, const std::string& text) {
    const auto v = parse_numbers(option, text, 3, "X,Y,Z");
    return {v[0], v[1], v[2]};
}

glm::dvec4 parse_vec4(const std::string& option, const std::string& text) {
    const auto v = parse_numbers(option, text, 4, "A,B,C,D");
    return {v[0], v[1], v[2], v[3]};
}

ShadingStrategy shading_strategy(const std::string& name) {
    return name == "forward"    ? ShadingStrategy::Forward
           : name == "deferred" ? ShadingStrategy::Deferred
                                : ShadingStrategy::Auto;
}

glm::ivec2 parse_size(const std::string& option, const std::string& text, int limit) {
    const std::size_t x = text.find('x');
    int w = 0, h = 0;
    bool ok = x != std::string::npos;
    if (ok) {
        const auto r1 = std::from_chars(text.data(), text.data() + x, w);
        const auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        ok = r1.ec == std::errc() && r1.ptr == text.data() + x && r2.ec == std::errc() &&
             r2.ptr == text.data() + text.size();
    }
    if (!ok) throw InputError(option, "expected WIDTHxHEIGHT, got '" + text + "'");
    if (w < 1 || h < 1 || w > limit || h > limit)
        throw InputError(
            option, "size " + text + " out of range (1.." + std::to_string(limit) + " per side)");
    return {w, h};
}

int checked_thread_count(const std::string& option, int requested) {
    if (requested < 0)
        throw InputError(
            option, "must be >= 0 (0: every hardware thread), not " + std::to_string(requested));
    const int used = render_thread_count(requested);
    if (requested > 0 && used < requested) {
        fmt::print(stderr,
                   "warning: {} {} is more than {} times the {} hardware threads; using "
                   "{}\n",
                   option, requested, kMaxThreadsPerHardwareThread,
                   used / kMaxThreadsPerHardwareThread, used);
        return used;
    }
    return requested;
}

namespace {
bool g_load_in_process = false;
bool g_allow_outside_references = false;
std::size_t g_max_instances = LoadOptions{}.max_instances;
std::size_t g_max_materials = LoadOptions{}.max_materials;
std::size_t g_max_load_triangles = LoadOptions{}.max_triangles;
int g_max_texture_side = LoadOptions{}.max_texture_side;
std::size_t g_max_texture_bytes = LoadOptions{}.max_texture_bytes;
std::size_t g_max_geometry_bytes = LoadOptions{}.max_geometry_bytes;
std::uint64_t g_max_triangulation_work = LoadOptions{}.max_triangulation_work;
}  // namespace

void set_max_triangulation_work(std::uint64_t max_work) {
    g_max_triangulation_work = max_work;
}

double g_max_load_seconds = LoadOptions{}.worker_timeout_seconds;

void set_max_load_seconds(double seconds) {
    g_max_load_seconds = seconds;
}

void set_max_geometry_bytes(std::size_t max_bytes) {
    g_max_geometry_bytes = max_bytes;
}

void set_texture_limits(int max_side, std::size_t max_bytes) {
    g_max_texture_side = max_side;
    g_max_texture_bytes = max_bytes;
}

void set_max_instances(std::size_t max_instances) {
    g_max_instances = max_instances;
}

void set_max_materials(std::size_t max_materials) {
    g_max_materials = max_materials;
}

void set_max_load_triangles(std::size_t max_triangles) {
    g_max_load_triangles = max_triangles;
}

void set_load_in_process(bool in_process) {
    g_load_in_process = in_process;
}

void set_allow_outside_references(bool allow) {
    g_allow_outside_references = allow;
}

LoadOptions command_load_options() {
    LoadOptions options;
    options.isolation = g_load_in_process ? LoadIsolation::InProcess : LoadIsolation::WorkerProcess;
    options.allow_outside_references = g_allow_outside_references;
    options.max_instances = g_max_instances;
    options.max_materials = g_max_materials;
    options.max_triangles = g_max_load_triangles;
    options.max_texture_side = g_max_texture_side;
    options.max_texture_bytes = g_max_texture_bytes;
    options.max_geometry_bytes = g_max_geometry_bytes;
    options.max_triangulation_work = g_max_triangulation_work;
    options.worker_timeout_seconds = g_max_load_seconds;
    return options;
}

std::string file_named_by(const std::string& model) {
    return "file named by " + model;
}

Scene load_scene_or_procedural(const std::string& spec, std::vector<std::string>* warnings,
                               OutputFiles* outputs,
                               std::vector<std::filesystem::path>* files_read_out) {
    if (is_procedural_spec(spec)) {
        check_scene_cap(spec);
        return make_procedural_scene(spec);
    }
    std::vector<std::string> found;
    std::vector<std::filesystem::path> files_read;
    Scene scene = load_scene(spec, command_load_options(), &found, &files_read);
    if (outputs != nullptr)
        for (const std::filesystem::path& file : files_read)
            outputs->check_input(file, file_named_by(spec));
    if (files_read_out != nullptr)
        files_read_out->insert(files_read_out->end(), files_read.begin(), files_read.end());
    for (const std::string& w : found) fmt::print(stderr, "warning: {}\n", w);
    if (warnings != nullptr) *warnings = std::move(found);
    return scene;
}

}  // namespace zraster::cli
