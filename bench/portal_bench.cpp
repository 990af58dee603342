// Portal culling on building:32x32 (docs/portals.md): whole frames at 1920x1080 on 2 threads
// from 32 cameras inside rooms (a fixed, seeded set; each iteration draws the next), with
// frustum culling only (always on: it cannot be switched off), with occlusion culling, with
// portal culling (cull rectangles, exact frustums), and with a PVS and the exact walk; and the
// cost of the walk itself. Counters: instances drawn per frame and the stage times.
// Run: build/portal_bench [--benchmark_filter=...].
#include <benchmark/benchmark.h>

#include <zraster/portals.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <memory>
#include <vector>

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

enum Variant { kFrustumOnly, kOcclusion, kRectangles, kPortals, kPvsPortals };
const char* const kVariantNames[] = {"frustum culling only", "occlusion culling",
                                     "portals (cull rectangles)", "portals (exact frustums)",
                                     "PVS + portals (exact)"};

void BM_BuildingFrame(benchmark::State& state) {
    const auto variant = Variant(state.range(0));
    const Scene& scene = variant == kPvsPortals ? building() : building_without_pvs();
    const std::vector<Camera> views = cameras();
    RenderOptions o;
    o.width = 1920;
    o.height = 1080;
    o.threads = 2;
    o.occlusion_cull = variant == kOcclusion;
    o.portal_cull = variant == kRectangles ? PortalCull::Rectangles
                    : variant >= kPortals  ? PortalCull::Frustum
                                           : PortalCull::Off;
    Renderer renderer;
    for (const Camera& c : views) {  // warm-up: allocations
        o.camera = c;
        renderer.render(scene, o);
    }
    double drawn = 0, walk = 0, vertex = 0, raster = 0;
    std::size_t k = 0;
    for (auto _ : state) {
        o.camera = views[k++ % views.size()];
        const RenderStats& s = renderer.render(scene, o).stats;
        drawn += double(s.instances - s.instances_frustum_culled - s.instances_occlusion_culled -
                        s.instances_portal_culled);
        walk += s.portal_ms;
        vertex += s.vertex_ms;
        raster += s.raster_ms;
    }
    const double frames = std::max(1.0, double(state.iterations()));
    state.counters["instances_drawn"] = drawn / frames;
    state.counters["walk_ms"] = walk / frames;
    state.counters["vertex_ms"] = vertex / frames;
    state.counters["raster_ms"] = raster / frames;
    state.SetLabel(std::string(kVariantNames[variant]) + ", " +
                   std::to_string(scene.instances.size()) + " instances");
}
BENCHMARK(BM_BuildingFrame)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();

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
