// Portal culling on building:32x32 (docs/portals.md): whole frames at 1920x1080 on 2 threads
// from 32 cameras inside rooms (a fixed, seeded set; each iteration draws the next), with no
// culling (the building flattened into one instance: instance frustum culling cannot be switched
// off, so every triangle then goes through the pipeline, left to clipping and per-triangle
// rejection), with frustum culling only, with occlusion culling, with portal culling (cull
// rectangles, exact frustums), and with a PVS and the exact walk; and the cost of the walk
// itself. Counters: instances drawn and triangles entering the pipeline (after instance culling)
// per frame, and the stage times.
// Run: build/portal_bench [--benchmark_filter=...].
#include <benchmark/benchmark.h>

#include <zraster/mesh.hpp>
#include <zraster/portals.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <memory>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>

#include "benchmark_main.hpp"
#include "render/portal_cull.hpp"

namespace zraster {
namespace {

constexpr int kRows = 32, kColumns = 32, kCameras = 32;

const Scene& building() {
    static const Scene scene = [] {
        Scene s = make_building(kRows, kColumns, 1);
        auto graph = std::make_shared<CellGraph>(*s.cells);
        graph->pvs = compute_pvs(*graph).visible;
        Scene with_pvs = s;
        with_pvs.cells = graph;
        return with_pvs;
    }();
    return scene;
}

const Scene& building_without_pvs() {
    static const Scene scene = [] {
        Scene s = building();
        auto graph = std::make_shared<CellGraph>(*s.cells);
        graph->pvs.clear();
        s.cells = graph;
        return s;
    }();
    return scene;
}

// The same triangles as one mesh in world space, one instance, no cells: nothing for instance
// culling to skip. One material (the first mesh's): Phong's cost per pixel does not depend on
// the material's values.
const Scene& building_flattened() {
    static const Scene scene = [] {
        const Scene& source = building_without_pvs();
        Mesh all;
        all.name = "building";
        all.material = source.meshes.front().material;
        for (const Instance& instance : source.instances) {
            const Mesh& mesh = source.meshes[instance.mesh];
            const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(instance.transform));
            const auto base = std::uint32_t(all.positions.size());
            for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
                all.positions.push_back(
                    glm::vec3(instance.transform * glm::vec4(mesh.positions[v], 1.0f)));
                if (v < mesh.normals.size())
                    all.normals.push_back(glm::normalize(normal_matrix * mesh.normals[v]));
            }
            for (std::uint32_t index : mesh.indices) all.indices.push_back(base + index);
        }
        if (all.normals.size() != all.positions.size()) {
            all.normals.clear();
            compute_angle_weighted_normals(all);
        }
        update_bounds(all);
        Scene s;
        s.name = "building:32x32 flattened";
        s.materials = source.materials;
        s.meshes.push_back(std::move(all));
        s.instances.push_back(Instance{0, glm::mat4(1.0f), std::nullopt, "building"});
        return s;
    }();
    return scene;
}

// Eyes at 1.6 in random rooms, away from the walls, looking level in a random direction.
std::vector<Camera> cameras() {
    SplitMix64 rng(7);
    std::vector<Camera> out;
    for (int k = 0; k < kCameras; ++k) {
        const double x = 4.0 * double(rng.next() % kColumns) + rng.uniform(0.8, 3.2);
        const double z = 4.0 * double(rng.next() % kRows) + rng.uniform(0.8, 3.2);
        const double yaw = rng.uniform(0.0, 6.283185307179586);
        Camera c;
        c.eye = {x, 1.6, z};
        c.target = c.eye + glm::dvec3(std::cos(yaw), 0.0, std::sin(yaw));
        c.fovy_degrees = 60.0;
        c.near = 0.05;
        c.far = 200.0;
        out.push_back(c);
    }
    return out;
}

enum Variant { kNoCulling, kFrustumOnly, kOcclusion, kRectangles, kPortals, kPvsPortals };
const char* const kVariantNames[] = {"no culling (one instance)", "frustum culling only",
                                     "occlusion culling",         "portals (cull rectangles)",
                                     "portals (exact frustums)",  "PVS + portals (exact)"};

void BM_BuildingFrame(benchmark::State& state) {
    const auto variant = Variant(state.range(0));
    const Scene& scene = variant == kPvsPortals  ? building()
                         : variant == kNoCulling ? building_flattened()
                                                 : building_without_pvs();
    const std::vector<Camera> views = cameras();
    RenderOptions o;
    o.width = 1920;
    o.height = 1080;
    o.threads = 2;
    o.occlusion_cull = variant == kOcclusion;
    // No culling: every triangle through the vertex stage and assembly (clusters' bounds would
    // back-face cull 64 triangles at a time before their vertices are read).
    o.cluster_culling = variant != kNoCulling;
    o.portal_cull = variant == kRectangles ? PortalCull::Rectangles
                    : variant >= kPortals  ? PortalCull::Frustum
                                           : PortalCull::Off;
    Renderer renderer;
    for (const Camera& c : views) {  // warm-up: allocations
        o.camera = c;
        renderer.render(scene, o);
    }
    double drawn = 0, triangles = 0, walk = 0, vertex = 0, raster = 0;
    std::size_t k = 0;
    for (auto _ : state) {
        o.camera = views[k++ % views.size()];
        const RenderStats& s = renderer.render(scene, o).stats;
        drawn += double(s.instances - s.instances_frustum_culled - s.instances_occlusion_culled -
                        s.instances_portal_culled);
        triangles += double(s.triangles_in);
        walk += s.portal_ms;
        vertex += s.vertex_ms;
        raster += s.raster_ms;
    }
    const double frames = std::max(1.0, double(state.iterations()));
    state.counters["instances_drawn"] = drawn / frames;
    state.counters["triangles_in"] = triangles / frames;
    state.counters["walk_ms"] = walk / frames;
    state.counters["vertex_ms"] = vertex / frames;
    state.counters["raster_ms"] = raster / frames;
    state.SetLabel(std::string(kVariantNames[variant]) + ", " +
                   std::to_string(scene.instances.size()) + " instances");
}
BENCHMARK(BM_BuildingFrame)->DenseRange(0, 5)->Unit(benchmark::kMillisecond)->UseRealTime();

// The walk alone (find the cell, walk, test the reached cells' instances), per camera.
void BM_PortalWalk(benchmark::State& state) {
    const Scene& scene = building_without_pvs();
    const std::vector<Camera> views = cameras();
    std::vector<Bounds3f> boxes;
    for (const Instance& i : scene.instances)
        boxes.push_back(scene.meshes[i.mesh].bounds.transformed(i.transform));
    detail::PortalWalk walk;
    detail::PortalWalkInput input;
    input.graph = scene.cells.get();
    input.mode = state.range(0) != 0 ? PortalCull::Frustum : PortalCull::Rectangles;
    input.width = 1920;
    input.height = 1080;
    input.world_boxes = boxes;
    std::size_t k = 0;
    double visits = 0;
    for (auto _ : state) {
        input.camera = views[k++ % views.size()];
        input.view_projection = input.camera.view_projection(16.0 / 9.0);
        detail::walk_portals(input, walk);
        visits += double(walk.visits);
        benchmark::DoNotOptimize(walk.kept.data());
    }
    state.counters["visits"] = visits / std::max(1.0, double(state.iterations()));
    state.SetLabel(state.range(0) != 0 ? "exact frustums" : "cull rectangles");
}
BENCHMARK(BM_PortalWalk)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace zraster

int main(int argc, char** argv) {
    return zraster::bench::run_benchmarks(argc, argv);
}
