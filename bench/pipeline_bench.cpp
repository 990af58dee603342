// Google Benchmark suites for the pipeline's stages and for whole frames:
//   triangle setup, front-end classification (SIMD and scalar), cluster culling (the per-cluster
//   test, building the bounds, the hash that checks them), the visibility kernel on 8x8
//   blocks (SIMD and scalar), the Phong shading kernel, and whole frames of the benchmark scenes
//   in depth-only and Phong modes at several resolutions and thread counts, with the stages'
//   mean times as counters (vertex stage, assembly, binning, tile raster with shading); and
//   the two entry points side by side (an owning Scene into the Renderer's targets, views of
//   the caller's buffers into the caller's targets).
// Run: build-bench/pipeline_bench [--benchmark_filter=...]. Speed is measured here, never in
// unit tests.
#include <benchmark/benchmark.h>

#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "benchmark_main.hpp"
#include "memory/huge_pages.hpp"
#include "raster/setup_lanes.hpp"
#include "raster/visibility_kernel.hpp"
#include "render/classify_kernel.hpp"
#include "render/cluster_cull.hpp"
#include "render/shade_kernel.hpp"
#include "render/word_hash.hpp"

namespace zraster {
namespace {

// Random small triangles (about `size` pixels across) in a 1920x1080 viewport, snapped.
std::vector<ScreenVertex> random_vertices(std::size_t n, double size, std::uint64_t seed) {
    SplitMix64 rng(seed);
    SetupSettings settings;
    settings.viewport = {1920, 1080};
    std::vector<ScreenVertex> out(n);
    for (std::size_t t = 0; t < n; t += 3) {
        const double cx = rng.uniform(0, 1920), cy = rng.uniform(0, 1080);
        for (std::size_t k = 0; k < 3 && t + k < n; ++k) {
            const double x = cx + rng.uniform(-size, size), y = cy + rng.uniform(-size, size);
            const glm::vec4 clip(float(x / 960.0 - 1.0), float(1.0 - y / 540.0),
                                 float(rng.uniform(0, 1)), 1.0f);
            to_screen(clip, settings, out[t + k]);
        }
    }
    return out;
}

void BM_TriangleSetup(benchmark::State& state) {
    const auto vertices = random_vertices(3 * 4096, double(state.range(0)), 1);
    SetupSettings settings;
    settings.viewport = {1920, 1080};
    settings.cull = CullMode::None;
    TriangleSetup setup;
    for (auto _ : state)
        for (std::size_t t = 0; t < vertices.size(); t += 3) {
            benchmark::DoNotOptimize(
                setup_triangle({vertices[t], vertices[t + 1], vertices[t + 2]}, settings, setup));
            benchmark::DoNotOptimize(setup);
        }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * 4096);
    state.SetLabel("triangles of about " + std::to_string(state.range(0)) + " px");
}
BENCHMARK(BM_TriangleSetup)->Arg(2)->Arg(10)->Arg(50);

// The same triangles set up eight at a time, as the tile rasterizer does it: vertices copied
// into lanes, set up in lanes (SIMD, or the scalar reference with range(1) = 0), each lane
// loaded as a TriangleSetup.
void BM_SetupLanes(benchmark::State& state) {
    const auto vertices = random_vertices(3 * 4096, double(state.range(0)), 1);
    const bool simd = state.range(1) != 0;
    SetupSettings settings;
    settings.viewport = {1920, 1080};
    settings.cull = CullMode::None;
    settings.screen_linear_planes = false;  // as perspective-correct frames set up
    TriangleSetup setup;
    detail::VertexLanes lanes;
    detail::SetupLanes out;
    for (auto _ : state)
        for (std::size_t t = 0; t < vertices.size(); t += 3 * detail::kSetupLanes) {
            for (int lane = 0; lane < detail::kSetupLanes; ++lane)
                for (int k = 0; k < 3; ++k)
                    lanes.set_vertex(k, lane, vertices[t + 3 * std::size_t(lane) + std::size_t(k)]);
            (simd ? detail::setup_lanes : detail::setup_lanes_scalar)(lanes, detail::kSetupLanes,
                                                                      settings, out, nullptr);
            for (int lane = 0; lane < detail::kSetupLanes; ++lane) {
                benchmark::DoNotOptimize(detail::load_setup(lanes, out, lane, settings, setup));
                benchmark::DoNotOptimize(setup);
            }
        }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * 4096);
    state.SetLabel(std::string(simd ? detail::setup_lanes_target() : "scalar") + ", about " +
                   std::to_string(state.range(0)) + " px");
}
BENCHMARK(BM_SetupLanes)->Args({2, 1})->Args({10, 1})->Args({10, 0});

void BM_ClassifyTriangles(benchmark::State& state) {
    const bool simd = state.range(0) != 0;
    const std::size_t triangles = 1 << 16;
    const auto screen = random_vertices(3 * triangles, 1.0, 2);
    std::vector<std::uint32_t> indices(screen.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = std::uint32_t(i);
    detail::ClassifyInput in;
    in.indices = indices.data();
    in.triangle_total = indices.size() / 3;
    in.vertex_total = std::uint32_t(screen.size());
    in.screen = screen.data();
    in.settings.viewport = {1920, 1080};
    auto out = std::make_unique<detail::ClassifyOutput>();
    for (auto _ : state)
        for (std::size_t t = 0; t < triangles; t += detail::ClassifyOutput::kMaxBatch) {
            if (simd)
                detail::classify_triangles(in, t, detail::ClassifyOutput::kMaxBatch, *out);
            else
                detail::classify_triangles_scalar(in, t, detail::ClassifyOutput::kMaxBatch, *out);
            benchmark::DoNotOptimize(out->count);
        }
    state.SetItemsProcessed(std::int64_t(state.iterations() * triangles));
    state.SetLabel(simd ? "simd (sub-pixel triangles, back-face culling)" : "scalar");
}
BENCHMARK(BM_ClassifyTriangles)->Arg(1)->Arg(0);

// The benchmark sphere's clusters, from its benchmark camera (about two thirds are culled).
struct SphereClusters {
    Mesh mesh = make_bench_sphere(1000000);
    std::vector<detail::ClusterBounds> bounds = detail::build_cluster_bounds(mesh);
    detail::ClusterView view;
    SphereClusters() {
        const Camera camera = fit_camera(mesh.positions);
        ClipSettings clip;
        clip.guard_x = float(kGuardBand / 960.0);
        clip.guard_y = float(kGuardBand / 540.0);
        SetupSettings setup;
        setup.viewport = {1920, 1080};
        view = detail::make_cluster_view(camera.view_projection(1920.0 / 1080.0), clip, setup);
    }
};

const SphereClusters& sphere_clusters() {
    static const SphereClusters clusters;
    return clusters;
}

void BM_ClusterTest(benchmark::State& state) {
    const SphereClusters& s = sphere_clusters();
    std::size_t culled = 0;
    for (auto _ : state) {
        culled = 0;
        for (const detail::ClusterBounds& b : s.bounds)
            culled += detail::cluster_is_culled(s.view, b);
        benchmark::DoNotOptimize(culled);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * s.bounds.size()));
    state.SetLabel(std::to_string(culled) + " of " + std::to_string(s.bounds.size()) +
                   " sphere:1000000 clusters culled");
}
BENCHMARK(BM_ClusterTest);

void BM_ClustersCulled(benchmark::State& state) {
    const SphereClusters& s = sphere_clusters();
    const detail::ClusterArrays arrays(s.bounds);
    std::vector<std::uint8_t> culled(arrays.count);
    for (auto _ : state) {
        detail::clusters_culled(s.view, arrays, 0, arrays.count, culled.data());
        benchmark::DoNotOptimize(culled.data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * arrays.count));
    state.SetLabel("simd, sphere:1000000 clusters");
}
BENCHMARK(BM_ClustersCulled);

void BM_BuildClusterBounds(benchmark::State& state) {
    const Mesh& mesh = sphere_clusters().mesh;
    for (auto _ : state) benchmark::DoNotOptimize(detail::build_cluster_bounds(mesh).data());
    state.SetItemsProcessed(std::int64_t(state.iterations() * mesh.triangle_count()));
    state.SetLabel("sphere:1000000, 1 thread");
}
BENCHMARK(BM_BuildClusterBounds)->Unit(benchmark::kMillisecond);

void BM_HashWords(benchmark::State& state) {
    const bool simd = state.range(0) != 0;
    std::vector<std::uint32_t> words(std::size_t(state.range(1)));
    SplitMix64 rng(3);
    for (auto& w : words) w = std::uint32_t(rng.next());
    for (auto _ : state)
        benchmark::DoNotOptimize(simd ? detail::hash_words(words.data(), words.size(), 0)
                                      : detail::hash_words_scalar(words.data(), words.size(), 0));
    state.SetBytesProcessed(std::int64_t(state.iterations() * words.size() * 4));
    state.SetLabel(simd ? "simd" : "scalar");
}
// A cluster's indices (192 words, from cache), and 16 MB (from memory).
BENCHMARK(BM_HashWords)->Args({1, 192})->Args({0, 192})->Args({1, 1 << 22});

void BM_VisibilityBlock(benchmark::State& state) {
    const bool simd = state.range(0) != 0;
    const bool attributes = state.range(1) != 0;
    const auto vertices = random_vertices(3 * 1024, 6.0, 3);
    SetupSettings settings;
    settings.viewport = {1920, 1080};
    settings.cull = CullMode::None;
    std::vector<TriangleSetup> setups;
    for (std::size_t t = 0; t < vertices.size(); t += 3) {
        TriangleSetup s;
        if (setup_triangle({vertices[t], vertices[t + 1], vertices[t + 2]}, settings, s) ==
                SetupResult::Visible &&
            s.max_x - s.min_x < 8 && s.max_y - s.min_y < 8 && s.min_x < 1900 && s.min_y < 1060)
            setups.push_back(s);
    }
    auto tile = std::make_unique<detail::TileBuffers>();
    std::fill(std::begin(tile->depth), std::end(tile->depth), 1.0f);
    std::int64_t pixels = 0;
    for (auto _ : state)
        for (const TriangleSetup& s : setups) {
            detail::BlockJob job;
            for (int k = 0; k < 3; ++k) {
                job.e[k] =
                    std::int32_t(s.edge_a[std::size_t(k)] * s.min_x +
                                 s.edge_b[std::size_t(k)] * s.min_y + s.edge_c[std::size_t(k)]);
                job.step_x[k] = std::int32_t(s.edge_a[std::size_t(k)]);
                job.step_y[k] = std::int32_t(s.edge_b[std::size_t(k)]);
            }
            job.planes = {s.depth, s.q, s.p1, s.p2, s.l1, s.l2};
            job.width = s.max_x - s.min_x + 1;
            job.height = s.max_y - s.min_y + 1;
            job.attributes = job.barycentrics = attributes;
            job.compare = CompareFunc::Always;  // every covered pixel does the full work
            pixels += simd ? detail::visibility_block(job, *tile)
                           : detail::visibility_block_scalar(job, *tile);
        }
    state.SetItemsProcessed(std::int64_t(state.iterations() * setups.size()));
    state.counters["fragments/s"] = benchmark::Counter(double(pixels), benchmark::Counter::kIsRate);
    state.SetLabel(std::string(simd ? detail::visibility_kernel_target() : "scalar") +
                   (attributes ? ", depth + ids + barycentrics" : ", depth only") +
                   ", triangles of about 6 px");
}
BENCHMARK(BM_VisibilityBlock)->Args({1, 0})->Args({1, 1})->Args({0, 0})->Args({0, 1});

// Random normals (facing +z) and positions in [-1, 1]^3, for `count` pixels.
void random_shading_inputs(SplitMix64& rng, int count, float* nx, float* ny, float* nz, float* px,
                           float* py, float* pz) {
    for (int i = 0; i < count; ++i) {
        nx[i] = float(rng.uniform(-1, 1));
        ny[i] = float(rng.uniform(-1, 1));
        nz[i] = float(rng.uniform(0, 1));
        px[i] = float(rng.uniform(-1, 1));
        py[i] = float(rng.uniform(-1, 1));
        pz[i] = float(rng.uniform(-1, 1));
    }
}

void BM_PhongShading(benchmark::State& state) {
    const bool simd = state.range(0) != 0;
    Material material;
    LightingModel lighting;
    const auto constants = detail::make_phong_constants(lighting, material, {0, 0, 5}, {0, 0, 1});
    auto batch = std::make_unique<detail::PhongBatch>();
    SplitMix64 rng(4);
    detail::PhongBatch& b = *batch;
    random_shading_inputs(rng, detail::kShadeBatch, b.nx, b.ny, b.nz, b.px, b.py, b.pz);
    std::fill_n(b.flip, detail::kShadeBatch, 0u);
    for (auto _ : state) {
        batch->count = detail::kShadeBatch;
        if (simd)
            detail::shade_phong_batch(constants, *batch);
        else
            detail::shade_phong_batch_scalar(constants, *batch);
        benchmark::DoNotOptimize(batch->r[0]);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * detail::kShadeBatch);
    state.SetLabel(simd ? "simd, pixels" : "scalar, pixels");
}
BENCHMARK(BM_PhongShading)->Arg(1)->Arg(0);

// The deferred row shader over whole tiles of tagged pixels (one material, every pixel): one
// tile (in L1 and L2), or 64 in turn (from L3 and memory).
void BM_TaggedTileShading(benchmark::State& state) {
    const int tiles = int(state.range(0));
    Material material;
    LightingModel lighting;
    const auto constants = detail::make_phong_constants(lighting, material, {0, 0, 5}, {0, 0, 1});
    std::vector<std::unique_ptr<detail::TileBuffers>> all(static_cast<std::size_t>(tiles));
    SplitMix64 rng(4);
    for (auto& tile : all) {
        tile = std::make_unique<detail::TileBuffers>();
        random_shading_inputs(rng, detail::TileBuffers::kPixels, tile->nx, tile->ny, tile->nz,
                              tile->wx, tile->wy, tile->wz);
        std::fill_n(tile->shade_tag, detail::TileBuffers::kPixels, 1u);
    }
    int next = 0;
    std::uint32_t rgba[detail::kTileStride];
    for (auto _ : state) {
        const auto& tile = all[std::size_t(next)];
        next = (next + 1) % tiles;
        for (int row = 0; row < detail::kTileStride; ++row)
            detail::shade_tagged_row(&constants, *tile,
                                     std::size_t(row) * detail::kTileStride,
                                     detail::kTileStride, rgba);
        benchmark::DoNotOptimize(rgba[0]);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * 64 * 64);
    state.SetLabel("pixels");
}
BENCHMARK(BM_TaggedTileShading)->Arg(1)->Arg(64);

// Whole frames: scene index, mode (0 depth, 1 phong), width, threads.
const char* const kScenes[] = {"sphere:1000000", "city:20000", "soup:1000000", "sphere:20000"};

const Scene& cached_scene(int index) {
    static std::map<int, Scene> scenes;
    auto it = scenes.find(index);
    if (it == scenes.end()) it = scenes.emplace(index, make_procedural_scene(kScenes[index])).first;
    return it->second;
}

void BM_Frame(benchmark::State& state) {
    Scene scene = cached_scene(int(state.range(0)));
    const bool phong = state.range(1) != 0;
    for (Material& m : scene.materials) {
        m.base_color = phong ? glm::vec3(0.8f, 0.75f, 0.7f) : glm::vec3(0.9f, 0.6f, 0.3f);
    }
    RenderOptions o;
    o.width = int(state.range(2));
    o.height = o.width * 9 / 16;
    o.threads = int(state.range(3));
    o.color_target = phong;
    o.shading = ShadingMode::Phong;
    o.camera = fit_camera(scene.world_positions());
    Renderer renderer;
    renderer.render(scene, o);  // warm-up: allocations
    // The stages' mean times per frame as counters (the renderer's own clocks): the vertex
    // stage, assembly, binning, and the tile raster (visibility and shading).
    double vertex = 0, assembly = 0, binning = 0, raster = 0;
    for (auto _ : state) {
        const RenderStats stats = renderer.render(scene, o).stats;
        vertex += stats.vertex_ms;
        assembly += stats.assembly_ms;
        binning += stats.binning_ms;
        raster += stats.raster_ms;
    }
    const double frames = std::max(1.0, double(state.iterations()));
    state.counters["vertex_ms"] = vertex / frames;
    state.counters["assembly_ms"] = assembly / frames;
    state.counters["binning_ms"] = binning / frames;
    state.counters["raster_ms"] = raster / frames;
    state.SetLabel(std::string(kScenes[state.range(0)]) + (phong ? " phong " : " depth ") +
                   std::to_string(o.width) + "x" + std::to_string(o.height) + ", " +
                   std::to_string(o.threads) + " thread(s)");
    state.SetItemsProcessed(std::int64_t(state.iterations() * scene.triangle_count()));
}
BENCHMARK(BM_Frame)
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {1920}, {1, 2}})
    ->ArgsProduct({{3}, {1}, {640, 1920, 3840}, {2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The entry points compared on one frame: scene index into kEntryScenes, path (0: owning Scene
// and the Renderer's targets; 1: views of the same arrays, tightly packed, into caller targets;
// 2: an interleaved vertex buffer, 16-bit indices where they fit, into caller targets; 3: as 1,
// the caller's targets in plain vectors), width, threads. Phong, color and depth targets either
// way; the caller's targets of paths 1 and 2 are advised for huge pages as the Renderer's own
// are (memory/huge_pages.hpp): 4 KiB pages cost the tiles' row writes TLB misses. sphere:70000
// stands in for the bunny (69,666 triangles, a model in the middle of the screen).
const char* const kEntryScenes[] = {"sphere:70000", "sphere:1000000"};

struct InterleavedVertex {
    glm::vec3 position, normal;
    glm::vec2 uv;
};

void BM_EntryPoint(benchmark::State& state) {
    static std::map<int, Scene> scenes;
    const int index = int(state.range(0));
    if (!scenes.count(index)) scenes.emplace(index, make_procedural_scene(kEntryScenes[index]));
    const Scene& scene = scenes.at(index);
    const int path = int(state.range(1));
    RenderOptions o;
    o.width = int(state.range(2));
    o.height = o.width * 9 / 16;
    o.threads = int(state.range(3));
    o.shading = ShadingMode::Phong;
    o.camera = fit_camera(scene.world_positions());

    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    SceneView view = view_of(scene, meshes, instances);
    std::vector<std::vector<InterleavedVertex>> vertices(scene.meshes.size());
    std::vector<std::vector<std::uint16_t>> indices16(scene.meshes.size());
    // Paths 4 and 5: 1 and 2 with the caller's promise that the targets are as the last frame
    // left them (TargetViews::unchanged_since_last_frame), as an engine's framebuffer is.
    const bool interleaved = path == 2 || path == 5;
    if (interleaved)
        for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
            const Mesh& mesh = scene.meshes[m];
            for (std::size_t i = 0; i < mesh.positions.size(); ++i)
                vertices[m].push_back({mesh.positions[i], mesh.normals[i],
                                       mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]});
            const InterleavedVertex* v = vertices[m].data();
            meshes[m].positions = {&v->position.x, vertices[m].size(), sizeof(InterleavedVertex)};
            meshes[m].normals = {&v->normal.x, vertices[m].size(), sizeof(InterleavedVertex)};
            if (!mesh.uvs.empty())
                meshes[m].uvs = {&v->uv.x, vertices[m].size(), sizeof(InterleavedVertex)};
            if (mesh.positions.size() <= 65536) {
                indices16[m].assign(mesh.indices.begin(), mesh.indices.end());
                meshes[m].indices = {indices16[m].data(), indices16[m].size(), IndexType::UInt16};
            }
        }
    const std::size_t pixels = std::size_t(o.width) * std::size_t(o.height);
    std::vector<std::uint8_t> color;
    std::vector<float> depth;
    if (path == 3) {
        color.resize(pixels * 4);
        depth.resize(pixels);
    } else {
        memory::resize_on_huge_pages(color, pixels * 4);
        memory::resize_on_huge_pages(depth, pixels);
    }
    TargetViews targets;
    targets.width = o.width;
    targets.height = o.height;
    targets.color = color.data();
    targets.depth = depth.data();
    targets.unchanged_since_last_frame = path >= 4;

    Renderer renderer;
    const auto frame = [&]() -> const RenderStats& {
        return path == 0 ? renderer.render(scene, o).stats : renderer.render(view, o, targets);
    };
    for (int warm_up = 0; warm_up < 2; ++warm_up) frame();  // allocations, cluster bounds
    double raster = 0;
    for (auto _ : state) raster += frame().raster_ms;
    state.counters["raster_ms"] = raster / std::max(1.0, double(state.iterations()));
    static const char* const kPaths[] = {"owning",
                                         "views",
                                         "interleaved views",
                                         "views, 4 KiB pages",
                                         "views, unchanged targets",
                                         "interleaved views, unchanged targets"};
    state.SetLabel(std::string(kEntryScenes[index]) + " " + kPaths[path] + " " +
                   std::to_string(o.width) + "x" + std::to_string(o.height) + ", " +
                   std::to_string(o.threads) + " thread(s)");
    state.SetItemsProcessed(std::int64_t(state.iterations() * scene.triangle_count()));
}
// One thread too: its instruction counts (valgrind --tool=callgrind) compare the paths without
// the run-to-run drift of frame times on a shared machine, or oneTBB's idle spinning.
BENCHMARK(BM_EntryPoint)
    ->ArgsProduct({{0, 1}, {0, 1, 2, 3, 4, 5}, {1920}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Transparency's cost: sphere:70000 (Phong) behind four nested quads facing the camera, the
// largest over 20% of the image and each next one over about half the one before (1 to 4 layers
// per pixel), opacity 0.4; arg 0 draws the quads opaque (RenderOptions::alpha_mode Opaque), arg
// 1 blends them. 1920x1080, on the second arg's threads (2; 1 for instruction counts under
// valgrind --tool=callgrind --toggle-collect='zraster::Renderer::render*').
void BM_Blended(benchmark::State& state) {
    Scene scene = make_procedural_scene("sphere:70000");
    RenderOptions o;
    o.width = 1920;
    o.height = 1080;
    o.threads = int(state.range(1));
    o.shading = ShadingMode::Phong;
    o.camera = fit_camera(scene.world_positions());
    o.alpha_mode = state.range(0) != 0 ? MaterialAlpha::Auto : MaterialAlpha::Opaque;
    // The quads between the eye and the sphere (the near plane moved nearer to make room),
    // spanning fractions of the view there.
    o.camera->near *= 0.2;
    const Camera& camera = *o.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double distance = 0.5 * glm::length(camera.target - camera.eye);
    const double half_height = 0.6 * distance * std::tan(glm::radians(camera.fovy_degrees) / 2.0);
    const double half_width = half_height * double(o.width) / double(o.height);
    Material glass;
    glass.base_color = {0.3f, 0.6f, 0.9f};
    glass.opacity = 0.4f;
    scene.materials.push_back(glass);
    for (const double side : {0.447, 0.32, 0.22, 0.15}) {  // of the view's width and height
        Mesh quad;
        const glm::dvec3 center = camera.eye + forward * distance * (0.6 - 0.05 * side);
        for (const auto& [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
            quad.positions.push_back(glm::vec3(center + right * (x * side * half_width) +
                                               up * (y * side * half_height)));
        quad.normals.assign(4, glm::vec3(-forward));
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.material = std::uint32_t(scene.materials.size() - 1);
        update_bounds(quad);
        scene.meshes.push_back(std::move(quad));
        Instance instance;
        instance.mesh = std::uint32_t(scene.meshes.size() - 1);
        scene.instances.push_back(instance);
    }
    Renderer renderer;
    renderer.render(scene, o);
    std::uint64_t blended = 0;
    for (auto _ : state) blended = renderer.render(scene, o).stats.pixels_blended;
    state.counters["blended_pixels_%"] = 100.0 * double(blended) / double(o.width * o.height);
    state.SetLabel(state.range(0) != 0 ? "quads blended" : "quads opaque");
}
BENCHMARK(BM_Blended)
    ->ArgsProduct({{0, 1}, {2, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace zraster

// (ZRASTER_BENCH_AVX2=1: the AVX2 kernels; see benchmark_main.hpp.)
int main(int argc, char** argv) {
    return zraster::bench::run_benchmarks(argc, argv);
}
