// libFuzzer target: argument vectors through the real command (tools/zraster/run.cpp): CLI11
// parsing, option validation, scene loading and rendering, output writing.
//
// The input is the arguments separated by NUL bytes. The work directory (the current directory
// during the run) holds small scenes the arguments may name (t.obj with t.mtl and t.png, t.ply,
// t.stl, t.off, t.gltf). Heavy requests are skipped before the run, judged by the same parser:
// images over 64x64 pixels or supersampled more than 4x4, procedural scenes over 2000
// triangles, more than 2 bench frames, more than 4 threads, and any argument containing '/'
// (reads and writes stay in the work directory).
//
// Oracles: the exit status is 0 or 2 (1 means an internal error: a bug), and a failed run leaves
// no file behind (outputs are written to a temporary and renamed).
#include <zraster/scenes.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "../tools/zraster/bench_command.hpp"
#include "../tools/zraster/info_command.hpp"
#include "../tools/zraster/render_command.hpp"
#include "../tools/zraster/run.hpp"
#include "../tools/zraster/svg_command.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace zraster;

constexpr std::uint64_t kMaxPixels = 64 * 64;
constexpr std::uint64_t kMaxProceduralN = 2000;

const std::map<std::string, std::string>& scene_fixtures() {
    static const std::map<std::string, std::string> files{
        {"t.obj",
         "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
         "usemtl m\nf 1/1 2/2 3/3\nf 2 4 3\n"},
        {"t.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
        {"t.stl",
         "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
         "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n"},
        {"t.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n3 0 1 2\n3 1 3 2\n"},
        {"t.gltf",
         R"({"asset":{"version":"2.0"},"buffers":[{"uri":"t.bin","byteLength":42}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,)"
         R"("byteLength":6}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,)"
         R"("type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,)"
         R"("count":3,"type":"SCALAR"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},)"
         R"("indices":1}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})"},
    };
    return files;
}

// Every file of the work directory with its contents: the fixtures after setup.
std::map<std::string, std::string> directory_contents(const std::filesystem::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        std::ifstream in(entry.path(), std::ios::binary);
        out[entry.path().filename().string()] =
            std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return out;
}

const std::filesystem::path& setup() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path& d = fuzz::work_dir();
        for (const auto& [name, text] : scene_fixtures()) fuzz::write_file(d / name, text);
        if (::chdir(d.c_str()) != 0) fuzz::fail("chdir to the work directory failed");
        return d;
    }();
    return dir;
}

// Restores the work directory to exactly the fixtures; returns false if it was not so.
bool restore(const std::filesystem::path& dir, const std::map<std::string, std::string>& fixtures) {
    bool clean = true;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (!fixtures.contains(name)) {
            clean = false;
            std::filesystem::remove_all(entry.path());
        }
    }
    for (const auto& [name, bytes] : fixtures) {
        std::ifstream in(dir / name, std::ios::binary);
        const std::string now{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        if (now != bytes) {
            clean = false;
            fuzz::write_file(dir / name, bytes);
        }
    }
    return clean;
}

bool small_size(const std::string& text) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) return true;  // refused by the command
    std::uint64_t w = 0, h = 0;
    const auto r1 = std::from_chars(text.data(), text.data() + x, w);
    const auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
    if (r1.ec != std::errc() || r2.ec != std::errc()) return true;
    return w * h <= kMaxPixels || w > (1u << 20) || h > (1u << 20);  // huge: refused anyway
}

bool small_scene(const std::string& spec) {
    if (!is_procedural_spec(spec) || spec.starts_with("builtin:")) return true;
    const std::size_t colon = spec.find(':');
    const std::size_t end = spec.find(':', colon + 1);
    std::uint64_t n = 0;
    const char* first = spec.data() + colon + 1;
    const char* last = spec.data() + (end == std::string::npos ? spec.size() : end);
    const auto r = std::from_chars(first, last, n);
    return r.ec != std::errc() || n <= kMaxProceduralN;
}

// Parses as run_zraster does and says whether the work asked for is small.
bool light_enough(std::vector<std::string> args) {
    for (const std::string& a : args) {
        if (a.find('/') != std::string::npos) return false;
        // A window (view) or a folder of pictures (explain): tested by tests/cli, not fuzzed.
        if (a == "view" || a == "explain") return false;
    }
    CLI::App app{"zraster", "zraster"};
    app.require_subcommand(0, 1);
    cli::RenderArguments render_args;
    cli::add_render_command(app, render_args);
    cli::InfoArguments info_args;
    cli::add_info_command(app, info_args);
    cli::BenchArguments bench_args;
    cli::add_bench_command(app, bench_args);
    cli::SvgArguments svg_args;
    cli::add_svg_command(app, svg_args);
    if (!args.empty() && args[0].starts_with("-") && args[0] != "-h" && args[0] != "--help")
        args.insert(args.begin(), "render");
    std::reverse(args.begin(), args.end());
    try {
        app.parse(args);
    } catch (const CLI::Error&) {
        return true;  // the command will refuse it too, cheaply
    }
    if (app.got_subcommand("info")) return small_scene(info_args.scene);
    if (app.got_subcommand("bench"))
        return small_scene(bench_args.scene) && small_size(bench_args.size) &&
               std::int64_t{bench_args.frames} + bench_args.warmup <= 2 && bench_args.threads <= 4;
    const auto small_render = [](const cli::RenderArguments& a) {
        return small_scene(a.scene) && small_size(a.size) && a.threads <= 4 && a.aa <= 4;
    };
    if (app.got_subcommand("svg")) return small_render(svg_args.render);
    return small_render(render_args);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path& dir = setup();
    static const std::map<std::string, std::string> fixtures = directory_contents(dir);

    std::vector<std::string> args;
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    while (!rest.empty() && args.size() < 32) {
        const std::size_t nul = rest.find('\0');
        args.emplace_back(rest.substr(0, std::min<std::size_t>(nul, 256)));
        rest = nul == std::string_view::npos ? std::string_view() : rest.substr(nul + 1);
    }
    if (!light_enough(args)) return -1;  // not added to the corpus

    const int status = cli::run_zraster(args);
    if (status != 0 && status != 2) fuzz::fail("exit status " + std::to_string(status));
    const bool clean = restore(dir, fixtures);
    if (status != 0 && !clean) fuzz::fail("a failed run left or changed files");
    return 0;
}
