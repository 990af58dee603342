// Loading through the worker process (LoadIsolation::WorkerProcess): the same scenes as in
// process, and a crash, hang or runaway allocation in the importer becomes a clear InputError.
// The faults are injected with the test hook the child runs before importing.
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "io/load_with_warnings.hpp"
#include "io/load_worker.hpp"
#include "io/worker_message.hpp"
#include "support/test_support.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include <unistd.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ZRASTER_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ZRASTER_TEST_ASAN 1
#endif

namespace zraster {
namespace {

const char* kPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n3 0 2 3\n";

LoadOptions worker_options() {
    LoadOptions o;
    o.isolation = LoadIsolation::WorkerProcess;
    return o;
}

// Sets the child's fault for one test.
class Hook {
  public:
    explicit Hook(io::WorkerTestHook hook) { io::set_worker_test_hook(hook); }
    ~Hook() { io::set_worker_test_hook(nullptr); }
    Hook(const Hook&) = delete;
    Hook& operator=(const Hook&) = delete;
};

std::filesystem::path ply_fixture(const std::string& test) {
    const auto path = test::temp_dir("io-worker-" + test) / "quad.ply";
    test::write_bytes(path, kPly);
    return path;
}

void expect_same_texture(const Texture* a, const Texture* b, const std::string& where) {
    ASSERT_EQ(a == nullptr, b == nullptr) << where;
    if (a == nullptr) return;
    EXPECT_EQ(a->width(), b->width()) << where;
    EXPECT_EQ(a->height(), b->height()) << where;
    ASSERT_EQ(a->levels(), b->levels()) << where;
    for (int l = 0; l < a->levels(); ++l) {
        const auto x = a->level_rgba(l), y = b->level_rgba(l);
        EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end())) << where << " level " << l;
    }
}

// Bit for bit: every array, name, material, texture, instance and warning.
void expect_same_scene(const io::LoadedScene& a_loaded, const io::LoadedScene& b_loaded,
                       const std::string& what) {
    const Scene& a = a_loaded.scene;
    const Scene& b = b_loaded.scene;
    EXPECT_EQ(a.name, b.name) << what;
    EXPECT_EQ(a_loaded.warnings, b_loaded.warnings) << what;
    ASSERT_EQ(a.materials.size(), b.materials.size()) << what;
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const Material &x = a.materials[i], &y = b.materials[i];
        const std::string where = what + " material " + std::to_string(i);
        EXPECT_EQ(x.name, y.name) << where;
        EXPECT_EQ(x.base_color, y.base_color) << where;
        EXPECT_EQ(x.ambient, y.ambient) << where;
        EXPECT_EQ(x.diffuse, y.diffuse) << where;
        EXPECT_EQ(x.specular, y.specular) << where;
        EXPECT_EQ(x.shininess, y.shininess) << where;
        EXPECT_EQ(x.opacity, y.opacity) << where;
        EXPECT_EQ(x.alpha_mode, y.alpha_mode) << where;
        EXPECT_EQ(x.alpha_cutoff, y.alpha_cutoff) << where;
        EXPECT_EQ(x.double_sided, y.double_sided) << where;
        expect_same_texture(x.base_color_texture.get(), y.base_color_texture.get(), where);
        expect_same_texture(x.opacity_texture.get(), y.opacity_texture.get(),
                            where + " opacity texture");
    }
    ASSERT_EQ(a.meshes.size(), b.meshes.size()) << what;
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh &x = a.meshes[i], &y = b.meshes[i];
        const std::string where = what + " mesh " + std::to_string(i);
        EXPECT_EQ(x.name, y.name) << where;
        EXPECT_EQ(x.material, y.material) << where;
        EXPECT_TRUE(x.positions == y.positions) << where;
        EXPECT_TRUE(x.normals == y.normals) << where;
        EXPECT_TRUE(x.uvs == y.uvs) << where;
        EXPECT_TRUE(x.colors == y.colors) << where;
        EXPECT_TRUE(x.indices == y.indices) << where;
        EXPECT_EQ(x.bounds.lo, y.bounds.lo) << where;
        EXPECT_EQ(x.bounds.hi, y.bounds.hi) << where;
    }
    ASSERT_EQ(a.instances.size(), b.instances.size()) << what;
    for (std::size_t i = 0; i < a.instances.size(); ++i) {
        const Instance &x = a.instances[i], &y = b.instances[i];
        const std::string where = what + " instance " + std::to_string(i);
        EXPECT_EQ(x.mesh, y.mesh) << where;
        EXPECT_TRUE(x.transform == y.transform) << where;
        EXPECT_EQ(x.shading, y.shading) << where;
        EXPECT_EQ(x.name, y.name) << where;
    }
}

void expect_same_load(const std::filesystem::path& path) {
    const io::LoadedScene in_process = test::load_with_warnings(path);
    const io::LoadedScene worker = test::load_with_warnings(path, worker_options());
    expect_same_scene(in_process, worker, path.string());
}

TEST(LoadWorker, CrashIsAnInputError) {
    const auto path = ply_fixture("segv");
    const Hook hook([] { std::raise(SIGSEGV); });
    test::expect_input_error([&] { load_scene(path, worker_options()); }, path,
                             "the importer crashed (signal 11, SIGSEGV)");
    // The same process loads the next file normally.
    io::set_worker_test_hook(nullptr);
    EXPECT_EQ(load_scene(path, worker_options()).triangle_count(), 2u);
}

TEST(LoadWorker, AbortIsAnInputError) {
    const auto path = ply_fixture("abort");
    const Hook hook([] { std::abort(); });
    test::expect_input_error([&] { load_scene(path, worker_options()); }, path,
                             "the importer crashed (signal 6, SIGABRT)");
}

TEST(LoadWorker, NonZeroExitIsAnInputError) {
    const auto path = ply_fixture("exit");
    const Hook hook([] { std::_Exit(7); });
    test::expect_input_error([&] { load_scene(path, worker_options()); }, path,
                             "the importer failed (exit status 7)");
}

// A process the child forks (as another thread of a service could fork at the same moment) keeps
// a copy of the pipe's write end: end of file comes late, yet the crash is seen at once.
TEST(LoadWorker, CrashIsSeenWhileAnotherProcessHoldsThePipe) {
    const auto path = ply_fixture("holder");
    const Hook hook([] {
        if (::fork() == 0) {
            std::this_thread::sleep_for(std::chrono::seconds(10));
            std::_Exit(0);
        }
        std::raise(SIGSEGV);
    });
    LoadOptions options = worker_options();
    options.worker_timeout_seconds = 60;
    const auto start = std::chrono::steady_clock::now();
    test::expect_input_error([&] { load_scene(path, options); }, path,
                             "the importer crashed (signal 11, SIGSEGV)");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(8));
}

TEST(LoadWorker, HangIsStoppedAtTheTimeout) {
    const auto path = ply_fixture("hang");
    const Hook hook([] {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    });
    LoadOptions options = worker_options();
    options.worker_timeout_seconds = 0.5;
    const auto start = std::chrono::steady_clock::now();
    test::expect_limit_exceeded([&] { load_scene(path, options); }, path, "worker_timeout_seconds",
                                "the importer took longer than 0.5 s and was stopped");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(LoadWorker, BusyLoopIsStoppedAtTheTimeout) {
    const auto path = ply_fixture("busy");
    const Hook hook([] {
        volatile std::uint64_t x = 0;
        for (;;) x = x + 1;
    });
    LoadOptions options = worker_options();
    options.worker_timeout_seconds = 0.5;
    test::expect_limit_exceeded([&] { load_scene(path, options); }, path, "worker_timeout_seconds",
                                "the importer took longer");
}

TEST(LoadWorker, UnboundedAllocationHitsTheMemoryLimit) {
    const auto path = ply_fixture("oom");
    const Hook hook([] {
        std::vector<char*> blocks;
        for (;;) {
            char* block = new char[std::size_t{16} << 20];
            std::memset(block, 1, std::size_t{16} << 20);
            blocks.push_back(block);
        }
    });
    LoadOptions options = worker_options();
    options.worker_memory_bytes = std::size_t{256} << 20;
    options.worker_timeout_seconds = 60;
#ifdef ZRASTER_TEST_ASAN
    // AddressSanitizer's allocator reports the failed mapping itself and exits with status 1.
    test::expect_input_error([&] { load_scene(path, options); }, path, "the importer");
#else
    test::expect_limit_exceeded([&] { load_scene(path, options); }, path, "worker_memory_bytes",
                                "the importer ran out of its 256 MiB (worker_memory_bytes)");
#endif
}

// By default the importer's budgets follow the file and the loader's budgets: a small file in
// a format zraster does not count before reading cannot take the importer past them.
TEST(LoadWorker, DefaultBudgetsFollowTheFileAndTheGeometryBudget) {
    LoadOptions options;
    EXPECT_EQ(worker_timeout_for(0, options), 30.0);
    EXPECT_EQ(worker_timeout_for(std::uint64_t{100} << 20, options), 130.0);
    EXPECT_EQ(worker_memory_for(1000, options), (std::size_t{256} << 20) + 4000 +
                                                    options.max_geometry_bytes +
                                                    2 * options.max_texture_bytes);
    options.max_geometry_bytes = std::size_t{2} << 30;
    options.max_texture_bytes = std::size_t{1} << 20;
    EXPECT_EQ(worker_memory_for(std::uint64_t{1} << 30, options),
              (std::size_t{256} << 20) + (std::size_t{4} << 30) + (std::size_t{2} << 30) +
                  (std::size_t{2} << 20));
    EXPECT_GE(worker_memory_for(~std::uint64_t{0}, options), std::size_t{1} << 61);  // saturates
    options.worker_timeout_seconds = 5;
    options.worker_memory_bytes = 123;
    EXPECT_EQ(worker_timeout_for(1 << 30, options), 5.0);
    EXPECT_EQ(worker_memory_for(1 << 30, options), 123u);
}

// A 38-byte NFF file whose sphere Assimp tessellates 10 times (21 million triangles): 6.4 GB
// in the importer. With the default memory budget it stops at 256 MiB + 152 bytes +
// max_geometry_bytes + 2 x max_texture_bytes, named as max_geometry_bytes, the flag a user raises.
TEST(LoadWorker, AFileThatExpandsInTheImporterStopsAtTheGeometryBudget) {
    const auto dir = test::temp_dir("io-worker-expands");
    const auto path = dir / "tess.nff";
    test::write_bytes(path, "tess 10\nf 1 0 0 0 0 0 0 0 0\ns 0 0 0 1\n");
    LoadOptions options = worker_options();
    options.max_geometry_bytes = std::size_t{64} << 20;
    options.max_texture_bytes = std::size_t{16} << 20;
#ifdef ZRASTER_TEST_ASAN
    test::expect_input_error([&] { load_scene(path, options); }, path, "the importer");
#else
    test::expect_limit_exceeded([&] { load_scene(path, options); }, path, "max_geometry_bytes",
                                "the importer ran out of its 353 MiB (256 MiB, 4 times the "
                                "file's size, max_geometry_bytes and twice max_texture_bytes) "
                                "reading it: it expands in a part of the NFF format zraster does "
                                "not count before reading");
#endif
}

TEST(LoadWorker, PreChecksRunWithoutAChild) {
    const auto dir = test::temp_dir("io-worker-prechecks");
    test::expect_input_error([&] { load_scene(dir / "missing.ply", worker_options()); },
                             dir / "missing.ply", "file not found");
    const auto huge = dir / "huge.ply";
    test::write_bytes(huge,
                      "ply\nformat ascii 1.0\nelement vertex 1099511627776\nproperty float x\n"
                      "end_header\n0\n");
    test::expect_input_error([&] { load_scene(huge, worker_options()); }, huge,
                             "truncated or malformed file: the PLY header declares");
}

TEST(LoadWorker, ImporterErrorsAreTheSame) {
    const auto dir = test::temp_dir("io-worker-errors");
    const auto bad = dir / "index.ply";
    test::write_bytes(bad,
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float "
                      "y\nproperty float z\nelement face 1\nproperty list uchar int "
                      "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    std::string in_process;
    try {
        load_scene(bad);
    } catch (const InputError& e) {
        in_process = e.what();
    }
    ASSERT_FALSE(in_process.empty());
    test::expect_input_error([&] { load_scene(bad, worker_options()); }, bad,
                             in_process.substr(bad.string().size() + 2));
}

TEST(LoadWorker, SmallFixturesLoadTheSame) {
    const auto dir = test::temp_dir("io-worker-fixtures");
    test::write_bytes(dir / "quad.ply", kPly);
    expect_same_load(dir / "quad.ply");
    test::write_bytes(dir / "tet.off",
                      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n"
                      "3 1 2 3\n");
    expect_same_load(dir / "tet.off");
    test::write_bytes(dir / "tri.stl",
                      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                      "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    expect_same_load(dir / "tri.stl");
    // glTF with an external buffer, a texture and two nodes placing the same mesh.
    std::vector<std::uint8_t> rgba(4 * 4 * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 37);
    write_png8(dir / "t.png", 4, 4, 4, rgba);
    const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::string bin(reinterpret_cast<const char*>(data), 9 * sizeof(float));
    bin.append(reinterpret_cast<const char*>(data + 9), 6 * sizeof(float));  // uvs
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    test::write_bytes(dir / "t.bin", bin);
    test::write_bytes(dir / "scene.gltf",
                      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
"nodes":[{"mesh":0,"name":"a"},{"mesh":0,"name":"b","translation":[2,0,0]}],
"meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
"materials":[{"name":"tex","pbrMetallicRoughness":{"baseColorTexture":{"index":0},"baseColorFactor":[1,0.5,0.25,1]}}],
"textures":[{"source":0}],"images":[{"uri":"t.png"}],
"buffers":[{"uri":"t.bin","byteLength":66}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24},{"buffer":0,"byteOffset":60,"byteLength":6}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},
{"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"}]})");
    const Scene gltf = load_scene(dir / "scene.gltf", worker_options());
    EXPECT_EQ(gltf.instances.size(), 2u);
    ASSERT_GE(gltf.materials.size(), 2u);
    EXPECT_NE(gltf.materials[1].base_color_texture, nullptr);
    expect_same_load(dir / "scene.gltf");
}

TEST(LoadWorker, SharedMeshesLoadTheSame) {
    ZRASTER_REQUIRE_SHARED_DATA();
    int compared = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(test::shared_data("meshes"))) {
        if (!entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext != ".ply" && ext != ".stl" && ext != ".gltf" && ext != ".glb" && ext != ".off" &&
            ext != ".3ds")
            continue;
        io::LoadedScene in_process;
        try {
            in_process = test::load_with_warnings(entry.path());
        } catch (const InputError& e) {
            // A file zraster refuses (BoxWithInfinites.glb) is refused the same way.
            test::expect_input_error([&] { load_scene(entry.path(), worker_options()); },
                                     entry.path(), e.cause());
            ++compared;
            continue;
        }
        expect_same_scene(in_process, test::load_with_warnings(entry.path(), worker_options()),
                          entry.path().string());
        ++compared;
    }
    EXPECT_GE(compared, 8);
}

// The parent's validation of what the child sends.
std::span<const std::uint8_t> byte_span(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// A quad whose instance has an empty name: the message ends with the last index, the instance
// count, the mesh, the transform, the shading byte and the name length.
std::string quad_message() {
    Mesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    compute_angle_weighted_normals(quad);
    update_bounds(quad);
    Scene scene = scene_from_meshes({quad});
    scene.instances[0].name.clear();
    return io::encode_scene_message({scene, {}, {}});
}

template <typename T>
void append(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// A scene message whose one mesh claims 2^60 positions.
std::string huge_count_message() {
    std::string payload;
    append(payload, std::uint32_t{0});  // source
    append(payload, std::uint32_t{0});  // warnings
    append(payload, std::uint32_t{0});  // files read
    append(payload, std::uint32_t{0});  // textures
    append(payload, std::uint32_t{1});  // materials
    append(payload, std::uint32_t{0});  // name
    for (int i = 0; i < 10; ++i) append(payload, 0.5f);
    append(payload, std::uint8_t(AlphaMode::Blend));
    append(payload, 0.5f);               // alpha cutoff
    append(payload, std::uint8_t{0});    // single-sided
    append(payload, ~std::uint32_t{0});  // no texture
    append(payload, ~std::uint32_t{0});  // no opacity texture
    append(payload, std::uint32_t{1});   // meshes
    append(payload, std::uint32_t{0});   // name
    append(payload, std::uint32_t{0});   // material
    append(payload, std::uint64_t{1} << 60);
    payload.append(64, '\0');
    std::string message = "ZRWM";
    append(message, io::kWorkerMessageVersion);
    append(message, std::uint32_t{1});
    append(message, std::uint32_t{0});
    append(message, std::uint64_t{payload.size()});
    return message + payload;
}

void expect_invalid(const std::string& message, std::string_view cause) {
    test::expect_input_error(
        [&] { io::decode_worker_message(byte_span(message), "m.ply", LoadOptions{}); }, "m.ply",
        cause);
}

TEST(WorkerMessage, RoundTrip) {
    const io::LoadedScene loaded = test::load_with_warnings(ply_fixture("roundtrip"));
    const std::string message = io::encode_scene_message(loaded);
    expect_same_scene(loaded, io::decode_worker_message(byte_span(message), "m.ply", {}), "quad");
}

// The fuzzer's seeds follow the current format: each scene seed is decoded past the material
// fields (a stale seed would be refused for its version or its layout, and fuzz nothing).
TEST(WorkerMessage, FuzzSeedsAreCurrent) {
    const std::filesystem::path seeds =
        std::filesystem::path(ZRASTER_SOURCE_DIR) / "fuzz/seeds/fuzz_worker_message";
    for (const char* name : {"quad", "textured_instances", "coordinates-beyond-1e30"}) {
        SCOPED_TRACE(name);
        std::ifstream in(seeds / name, std::ios::binary);
        const std::string message((std::istreambuf_iterator<char>(in)), {});
        ASSERT_FALSE(message.empty());
        try {
            const io::LoadedScene scene = io::decode_worker_message(byte_span(message), "m", {});
            EXPECT_FALSE(scene.scene.meshes.empty());
        } catch (const InputError& e) {
            // Only the seed about huge coordinates is refused, for them.
            EXPECT_EQ(std::string(name), "coordinates-beyond-1e30") << e.what();
            EXPECT_NE(std::string(e.what()).find("position"), std::string::npos) << e.what();
        }
    }
}

TEST(WorkerMessage, RefusesMalformedMessages) {
    const std::string good = quad_message();
    expect_invalid("", "invalid result: truncated header");
    expect_invalid("XRWM" + good.substr(4), "invalid result: bad magic");
    std::string version = good;
    version[4] = 5;  // a child of a zraster before the files read
    expect_invalid(version, "format version 5, expected 6");
    expect_invalid(good.substr(0, good.size() - 1), "the header says");
    std::string longer = good + "x";
    expect_invalid(longer, "the header says");
    // The last index points past the 4 vertices.
    const std::size_t last_index = good.size() - (4 + 4 + 64 + 1 + 4) - 4;
    std::string index = good;
    index[last_index] = 9;
    expect_invalid(index, "index 9 out of range");
    // Normals are one per position, always (fuzz_worker_message found them accepted empty).
    Mesh bare;
    bare.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    bare.indices = {0, 1, 2};
    update_bounds(bare);
    expect_invalid(io::encode_scene_message({scene_from_meshes({bare}), {}, {}}),
                   "mesh 0: normals not one per position");
    // A count of 2^60 positions is refused before anything is allocated.
    expect_invalid(huge_count_message(), "positions: 1152921504606846976 elements do not fit");
    LoadOptions limit;
    limit.max_triangles = 1;
    test::expect_input_error([&] { io::decode_worker_message(byte_span(good), "m.ply", limit); },
                             "m.ply", "more triangles than the limit (1)");
}

// A budget's refusal crosses the pipe as a LimitExceeded with its field's name; a name that is
// not a field's is an invalid result.
TEST(WorkerMessage, LimitExceededKeepsTheLimitsName) {
    const std::string message = io::encode_limit_message("max_instances", "too many placements");
    try {
        io::decode_worker_message(byte_span(message), "m.gltf", LoadOptions{});
        ADD_FAILURE() << "no exception";
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), "max_instances");
        EXPECT_EQ(std::string(e.what()), "m.gltf: too many placements");
    }
    for (const std::string& bad : std::vector<std::string>{"", "Max", "max instances",
                                                           "max_instances\n", std::string(65, 'a')})
        expect_invalid(io::encode_limit_message(bad, "x"),
                       "a limit name that is not a LoadOptions field");
    expect_invalid(io::encode_limit_message("max_triangles", "x") + "y", "the header says");
}

// A 2 x 1 RGBA texture with `alpha` in its second texel.
std::shared_ptr<const Texture> two_texels(std::uint8_t alpha) {
    const std::uint8_t rgba[8] = {10, 20, 30, 255, 40, 50, 60, alpha};
    return std::make_shared<const Texture>(2, 1, rgba);
}

// Every alpha mode, cutoff and texture arrangement crosses intact, and a texture two materials
// (or one material's two slots) share stays one texture.
TEST(WorkerMessage, RoundTripKeepsMaterialAlpha) {
    const auto shared = two_texels(255), cutout = two_texels(0);
    Scene scene = load_scene(ply_fixture("roundtrip-alpha"));
    Material opaque, mask, blend;
    opaque.name = "opaque";
    opaque.alpha_mode = AlphaMode::Opaque;
    opaque.base_color_texture = cutout;
    mask.name = "mask";
    mask.alpha_mode = AlphaMode::Mask;
    mask.alpha_cutoff = 0.3f;
    mask.opacity = 0.75f;
    mask.base_color_texture = shared;
    mask.opacity_texture = cutout;
    blend.name = "blend";
    blend.alpha_mode = AlphaMode::Blend;
    blend.opacity = 0.25f;
    blend.alpha_cutoff = 1.0f;
    blend.base_color_texture = shared;
    blend.opacity_texture = shared;
    blend.double_sided = true;
    scene.materials.insert(scene.materials.end(), {opaque, mask, blend});
    const io::LoadedScene sent{scene, {"m.ply: a warning"}, {"/models/a b.png", "/models/m.bin"}};
    const std::string message = io::encode_scene_message(sent);
    const io::LoadedScene received = io::decode_worker_message(byte_span(message), "m.ply", {});
    expect_same_scene(sent, received, "alpha");
    EXPECT_EQ(received.files_read, sent.files_read);
    // A file read must be an absolute path (the parent keeps outputs off it).
    expect_invalid(io::encode_scene_message({scene, {}, {"relative.png"}}),
                   "file read 0 is not an absolute path");
    const Scene& decoded = received.scene;
    ASSERT_EQ(decoded.materials.size(), scene.materials.size());
    const std::size_t n = decoded.materials.size();
    EXPECT_EQ(decoded.materials[n - 1].base_color_texture,
              decoded.materials[n - 1].opacity_texture);
    EXPECT_EQ(decoded.materials[n - 2].base_color_texture,
              decoded.materials[n - 1].base_color_texture);
    EXPECT_EQ(decoded.materials[n - 2].opacity_texture,
              decoded.materials[n - 3].base_color_texture);
    EXPECT_TRUE(decoded.materials[n - 3].base_color_texture->has_translucent_texels());
}

// The parent refuses material alpha the loader never produces: an unknown mode, a cutoff or
// opacity outside [0, 1] or NaN, an opacity texture that is not in the message.
TEST(WorkerMessage, RefusesBadMaterialAlpha) {
    Mesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};
    compute_angle_weighted_normals(tri);
    update_bounds(tri);
    const auto message_with = [&](auto change) {
        Scene scene = scene_from_meshes({tri});
        change(scene.materials.at(0));
        return io::encode_scene_message({scene, {}, {}});
    };
    expect_invalid(message_with([](Material& m) { m.alpha_mode = static_cast<AlphaMode>(3); }),
                   "material 0: unknown alpha mode 3");
    for (const float cutoff : {-0.1f, 1.5f, std::nanf("")}) {
        SCOPED_TRACE(cutoff);
        expect_invalid(message_with([&](Material& m) { m.alpha_cutoff = cutoff; }),
                       "material 0: alpha cutoff not in [0, 1]");
    }
    expect_invalid(message_with([](Material& m) { m.opacity = 1.5f; }),
                   "material 0: opacity outside [0, 1]");
    expect_invalid(message_with([](Material& m) { m.opacity = std::nanf(""); }),
                   "material 0 has non-finite values");
    // double_sided is a byte of 0 or 1: the one after the cutoff, before the texture indices.
    std::string sides = message_with([](Material& m) { m.alpha_cutoff = 0.125f; });
    const float cutoff = 0.125f;
    const std::size_t cutoff_at =
        sides.find(std::string(reinterpret_cast<const char*>(&cutoff), 4));
    ASSERT_NE(cutoff_at, std::string::npos);
    ASSERT_EQ(sides[cutoff_at + 4], '\0');
    sides[cutoff_at + 4] = 2;
    expect_invalid(sides, "material 0: double_sided is 2, not 0 or 1");
    // No texture in the message, and the material's opacity texture index set to 0.
    std::string missing = message_with([](Material&) {});
    const std::string none(8, '\xff');  // the two texture indices, ~0 each
    const std::size_t at = missing.find(none);
    ASSERT_NE(at, std::string::npos);
    missing.replace(at + 4, 4, std::string(4, '\0'));
    expect_invalid(missing, "material 0 names a missing opacity texture");
}

// Vertex colors cross the pipe as they are, and the parent refuses what the loader never
// produces: colors not one per position, a component outside [0, 1] or NaN.
TEST(WorkerMessage, VertexColors) {
    Mesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.indices = {0, 1, 2};
    tri.colors = {{1, 0, 0, 0.25f}, {0, 1, 0, 0.5f}, {0, 0, 1, 1}};
    compute_angle_weighted_normals(tri);
    update_bounds(tri);
    const io::LoadedScene sent{scene_from_meshes({tri}), {}, {}};
    const std::string message = io::encode_scene_message(sent);
    expect_same_scene(sent, io::decode_worker_message(byte_span(message), "m.ply", {}), "colors");
    const auto message_with = [&](auto change) {
        Scene scene = scene_from_meshes({tri});
        change(scene.meshes.at(0).colors);
        return io::encode_scene_message({scene, {}, {}});
    };
    expect_invalid(message_with([](std::vector<glm::vec4>& c) { c.pop_back(); }),
                   "mesh 0: colors not one per position");
    for (const float bad : {-0.5f, 1.5f, std::nanf("")}) {
        SCOPED_TRACE(bad);
        expect_invalid(message_with([&](std::vector<glm::vec4>& c) { c[1].w = bad; }),
                       "mesh 0: a vertex color is outside [0, 1]");
    }
}

TEST(WorkerMessage, ErrorMessages) {
    test::expect_input_error(
        [&] {
            io::decode_worker_message(byte_span(io::encode_error_message(
                                          io::WorkerMessageKind::InputError, "bad\nthing")),
                                      "m.ply", {});
        },
        "m.ply", "bad thing");
    test::expect_input_error(
        [&] {
            io::decode_worker_message(
                byte_span(io::encode_error_message(io::WorkerMessageKind::OutOfMemory, "")),
                "m.ply", {});
        },
        "m.ply", "the importer ran out of memory");
    EXPECT_THROW(io::decode_worker_message(
                     byte_span(io::encode_error_message(io::WorkerMessageKind::InternalError, "x")),
                     "m.ply", {}),
                 std::runtime_error);
}

}  // namespace
}  // namespace zraster
