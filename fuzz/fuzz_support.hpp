// Shared by the libFuzzer targets: a private working directory with small companion files, and
// the checks every loaded scene must pass (the fuzzers' oracles besides the sanitizers).
#pragma once
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace zraster::fuzz {

// Prints the broken invariant and aborts: libFuzzer saves the input as a crash.
[[noreturn]] inline void fail(const std::string& what) {
    std::fprintf(stderr, "zraster fuzz invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

inline void write_file(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out.good()) fail("cannot write " + path.string());
}

// A 4x4 RGBA checkerboard, so that references to "t.png" from a fuzzed MTL or glTF resolve.
inline void write_texture_fixture(const std::filesystem::path& path) {
    std::vector<std::uint8_t> rgba(4 * 4 * 4);
    for (std::size_t i = 0; i < 16; ++i) {
        const std::uint8_t v = ((i % 4) + (i / 4)) % 2 ? 255 : 0;
        rgba[4 * i] = v;
        rgba[4 * i + 1] = static_cast<std::uint8_t>(255 - v);
        rgba[4 * i + 2] = 128;
        rgba[4 * i + 3] = 255;
    }
    write_png8(path, 4, 4, 4, rgba);
}

// Companion files a fuzzed input may name: a material library, a texture, a glTF buffer
// (one triangle: 3 float positions then 3 uint16 indices) and an OBJ object (o.obj). Then every file, at most 1 MiB, of
// the directories in $ZRASTER_FUZZ_FIXTURES (colon-separated; fuzz.sh passes the shared glTF
// folders so that their .bin buffers and textures resolve).
inline void write_fixtures(const std::filesystem::path& dir) {
    write_file(dir / "t.mtl",
               "newmtl m\nKd 0.5 0.6 0.7\nKs 0.2 0.2 0.2\nNs 20\nd 1\nmap_Kd t.png\n"
               "newmtl n\nKd 1 0 0\n");
    write_texture_fixture(dir / "t.png");
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    write_file(dir / "t.bin", bin);
    // An object a LightWave scene may load (LoadObjectLayer 1 o.obj).
    write_file(dir / "o.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    if (const char* list = std::getenv("ZRASTER_FUZZ_FIXTURES")) {
        std::string_view rest(list);
        while (!rest.empty()) {
            const std::size_t colon = rest.find(':');
            const std::filesystem::path source(std::string(rest.substr(0, colon)));
            rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
            std::error_code ec;
            for (const auto& entry : std::filesystem::directory_iterator(source, ec)) {
                if (entry.is_regular_file(ec) && entry.file_size(ec) <= (1u << 20))
                    std::filesystem::copy_file(entry.path(), dir / entry.path().filename(),
                                               std::filesystem::copy_options::skip_existing, ec);
            }
        }
    }
}

// A fresh directory per process ($TMPDIR or /tmp), with the fixtures, removed at exit.
inline const std::filesystem::path& work_dir() {
    static const std::filesystem::path dir = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "zraster-fuzz-XXXXXX");
        if (::mkdtemp(pattern.data()) == nullptr) fail("mkdtemp failed");
        const std::filesystem::path d(pattern);
        write_fixtures(d);
        static const std::filesystem::path to_remove = d;
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(to_remove, ec);
        });
        return d;
    }();
    return dir;
}

inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What load_scene promises about a scene it returns (include/zraster/load.hpp, mesh.hpp) and
// the warnings it gave with it.
inline void check_loaded_scene(const Scene& scene, const std::vector<std::string>& warnings = {}) {
    if (scene.materials.empty()) fail("no default material");
    if (scene.instances.empty()) fail("a loaded scene without instances");
    for (const Mesh& mesh : scene.meshes) {
        const std::size_t n = mesh.positions.size();
        if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) fail("bad index count");
        for (std::uint32_t i : mesh.indices)
            if (i >= n) fail("index out of range in mesh " + mesh.name);
        for (const glm::vec3& p : mesh.positions)
            if (!finite(p)) fail("non-finite position in mesh " + mesh.name);
        if (mesh.normals.size() != n) fail("normals not one per position");
        for (const glm::vec3& normal : mesh.normals) {
            if (!finite(normal)) fail("non-finite normal in mesh " + mesh.name);
            if (std::fabs(glm::length(normal) - 1.0f) > 1e-3f)
                fail("normal (" + std::to_string(normal.x) + ", " + std::to_string(normal.y) +
                     ", " + std::to_string(normal.z) + ") not unit length in mesh " + mesh.name);
        }
        if (!mesh.uvs.empty() && mesh.uvs.size() != n) fail("uvs not one per position");
        if (!mesh.colors.empty() && mesh.colors.size() != n) fail("colors not one per position");
        for (const glm::vec4& c : mesh.colors)
            if (!(c.x >= 0.0f && c.x <= 1.0f && c.y >= 0.0f && c.y <= 1.0f && c.z >= 0.0f &&
                  c.z <= 1.0f && c.w >= 0.0f && c.w <= 1.0f))
                fail("vertex color outside [0, 1] in mesh " + mesh.name);
        if (mesh.material >= scene.materials.size()) fail("material index out of range");
    }
    for (const Instance& instance : scene.instances)
        if (instance.mesh >= scene.meshes.size()) fail("instance names a missing mesh");
    for (const Material& m : scene.materials) {
        if (!(m.opacity >= 0.0f && m.opacity <= 1.0f)) fail("opacity outside [0, 1]: " + m.name);
        if (!(m.alpha_cutoff >= 0.0f && m.alpha_cutoff <= 1.0f))
            fail("alpha cutoff outside [0, 1]: " + m.name);
        if (m.alpha_mode > AlphaMode::Blend) fail("unknown alpha mode: " + m.name);
    }
    for (const std::string& w : warnings)
        if (w.find('\n') != std::string::npos) fail("multi-line warning: " + w);
}

// An InputError is the expected answer to a bad file: one line, "FILE: cause".
inline void check_input_error(const InputError& e, const std::string& file) {
    const std::string what = e.what();
    if (what.find('\n') != std::string::npos) fail("multi-line error: " + what);
    if (e.file() != file) fail("error names '" + e.file() + "', not the file: " + what);
    if (e.cause().empty()) fail("error without a cause");
}

// How the loader targets run Assimp: in this process (the default: the sanitizers see Assimp's
// memory errors, as far as they can in an uninstrumented library) or, with
// ZRASTER_FUZZ_LOAD_ISOLATION=worker, in the worker process the command uses (the product
// configuration: a crash in Assimp is a refused file; our pre-checks, the worker protocol, the
// parent's validation and the rendering stay in this process, instrumented).
inline LoadIsolation fuzz_load_isolation() {
    static const LoadIsolation isolation = [] {
        const char* mode = std::getenv("ZRASTER_FUZZ_LOAD_ISOLATION");
        return mode != nullptr && std::string_view(mode) == "worker" ? LoadIsolation::WorkerProcess
                                                                     : LoadIsolation::InProcess;
    }();
    return isolation;
}

// A scene that loaded (or decoded) must render: 24x16, one thread, a color target of that size.
// With the default camera, unless a finite coordinate lies beyond what a camera can frame
// (kMaxCoordinate, camera.hpp: the default camera refuses to fit it); then with a fixed camera,
// which the pipeline must take whatever the coordinates.
inline void check_renders(const Scene& scene, const std::string& what) {
    RenderOptions render_options;
    render_options.width = 24;
    render_options.height = 16;
    render_options.threads = 1;
    for (const glm::vec3& p : scene.world_positions())
        for (int k = 0; k < 3; ++k)
            if (std::isfinite(p[k]) && std::abs(double(p[k])) > kMaxCoordinate) {
                Camera fixed;
                fixed.eye = {0.0, 0.0, 5.0};
                fixed.target = {0.0, 0.0, 0.0};
                fixed.near = 0.1;
                fixed.far = 100.0;
                render_options.camera = fixed;
            }
    try {
        const RenderResult result = render(scene, render_options);
        if (result.targets.color.size() != 24u * 16u * 4u) fail("color target size");
    } catch (const InputError& e) {
        fail("render refused " + what + ": " + e.what());
    }
}

// Loads `bytes` as a file named input<extension> in the work directory, checks the result and
// draws it small (the loaded geometry through the whole pipeline).
// The loaders' options under fuzzing.
inline LoadOptions fuzz_load_options() {
    LoadOptions options;
    options.max_triangles = 200'000;  // keeps each run short; the limit check itself is tested
    options.isolation = fuzz_load_isolation();
    options.worker_timeout_seconds = 15;  // under libFuzzer's -timeout=20
    options.worker_memory_bytes = std::size_t{1} << 30;
    return options;
}

inline void fuzz_load(const std::uint8_t* data, std::size_t size, const std::string& extension) {
    const std::filesystem::path path = work_dir() / ("input" + extension);
    write_file(path, std::string_view(reinterpret_cast<const char*>(data), size));
    const LoadOptions options = fuzz_load_options();
    Scene scene;
    std::vector<std::string> warnings;
    try {
        scene = load_scene(path, options, &warnings);
    } catch (const InputError& e) {
        check_input_error(e, path.string());
        return;
    }
    check_loaded_scene(scene, warnings);
    (void)describe_scene(scene, warnings);
    check_renders(scene, "a loaded scene");
}

}  // namespace zraster::fuzz
