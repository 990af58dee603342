// libFuzzer target: argument vectors through the real command (tools/zraster/run.cpp): CLI11
// parsing, option validation, scene loading and rendering, output writing.
//
// The input is the arguments separated by NUL bytes. The work directory (the current directory
// during the run) holds small scenes the arguments may name (t.obj with t.mtl and t.png, t.ply,
// t.stl, t.off, t.gltf). Heavy requests are not skipped: the fuzzer sets the command's caps
// (tools/zraster/command_caps.hpp) small, 64x64 pixels of 4x4 samples, procedural scenes of 500
// triangles, 3 bench frames, 4 threads, so that large --size, --aa, --threads, --frames,
// --warmup, --jobs and scene sizes reach the command and are refused or clamped by its own checks.
// Arguments containing '/' are skipped (reads and writes stay in the work directory), and so are
// `view` (a window) and `explain` (a folder of pictures).
//
// Oracles: the exit status is 0 or 2 (1 means an internal error: a bug; `batch` may also exit 3,
// some files failed), and a run that exits 2 leaves no file behind (outputs are written to a
// temporary and renamed; batch's output folder is removed if its plan is refused).
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "../tools/zraster/command_caps.hpp"
#include "../tools/zraster/run.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace zraster;

// Each run stays fast: 64x64 pixels of 4x4 samples, scenes of 500 triangles.
constexpr std::uint64_t kMaxSamples = 64 * 64 * 16;
constexpr std::uint64_t kMaxSceneTriangles = 500;

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
        // The command's own checks refuse or clamp what is past these (command_caps.hpp).
        cli::CommandCaps caps;
        caps.max_samples = kMaxSamples;
        caps.max_scene_triangles = kMaxSceneTriangles;
        caps.max_frames = 3;
        caps.max_threads = 4;
        cli::set_command_caps(caps);
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

// Runs that would leave the work directory or open a window are not made: paths with '/' (reads
// and writes stay in the work directory), `view` (a window) and `explain` (a folder of pictures),
// tested by tests/cli. Everything else runs; its size is the command's to check.
bool runnable(const std::vector<std::string>& args) {
    for (const std::string& a : args) {
        if (a.find('/') != std::string::npos) return false;
        if (a == "view" || a == "explain") return false;
    }
    return true;
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
    if (!runnable(args)) return -1;  // not added to the corpus

    const int status = cli::run_zraster(args);
    // `zraster batch` exits 3 when some files failed and the others were rendered: their outputs
    // and the batch's log stay, by design (docs/batch.md).
    const bool batch = std::find(args.begin(), args.end(), "batch") != args.end();
    const bool some_failed = batch && status == 3;
    if (status != 0 && status != 2 && !some_failed)
        fuzz::fail("exit status " + std::to_string(status));
    const bool clean = restore(dir, fixtures);
    if (status == 2 && !clean) fuzz::fail("a failed run left or changed files");
    return 0;
}
