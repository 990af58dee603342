// libFuzzer target: cluster back-face culling (src/render/cluster_cull.hpp) against the exact
// path. The input bytes shape one cluster of 64 triangles (a patch of a grid, bent, scaled from
// far below a pixel to huge, moved anywhere, each vertex nudged, any vertex replaced by a
// hostile value: NaN, infinities, denormals, 1e30) and a camera, model matrix, viewport and cull
// settings. An empty input is a cluster facing away in the middle of the view, which the bound
// culls: the fuzzer starts from the branch that matters.
//
// Oracle: when cluster_is_culled() says so, the vertex stage's scalar path (float transform,
// outcodes, snap) and classify_triangle() must cull every triangle of the cluster: no vertex
// outside the view volume, no degenerate triangle, none facing the kept way.
#include <zraster/camera.hpp>
#include <zraster/mesh.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "render/cluster_cull.hpp"
#include "render/vertex_kernel.hpp"

namespace {

using namespace zraster;
using namespace zraster::detail;

// center + up to `spread` either way; center itself when the input has run out.
double around(FuzzedDataProvider& in, double center, double spread) {
    const double p = in.ConsumeProbability<double>();
    return in.ConsumeBool() ? center - spread * p : center + spread * p;
}

float hostile(FuzzedDataProvider& in) {
    static constexpr float kPalette[] = {std::numeric_limits<float>::quiet_NaN(),
                                         std::numeric_limits<float>::infinity(),
                                         -std::numeric_limits<float>::infinity(),
                                         1e30f,
                                         -1e30f,
                                         FLT_MAX,
                                         1e-40f,
                                         -0.0f,
                                         0x1p20f};
    return in.PickValueInArray(kPalette);
}

Mesh patch(FuzzedDataProvider& in) {
    const glm::dvec3 center(around(in, 0, 8), around(in, 0, 8), around(in, 0, 12));
    // Facing away from a camera on +z by default.
    const glm::dvec3 normal =
        glm::normalize(glm::dvec3(around(in, 0, 2), around(in, 0, 2), around(in, -1, 2)) +
                       glm::dvec3(0, 0, -1e-9));
    const glm::dvec3 u = glm::normalize(glm::cross(normal, glm::dvec3(0.3, 0.5, 0.8)));
    const glm::dvec3 v = glm::cross(normal, u);
    const double size = std::pow(10.0, around(in, 0, 8));
    const double bend = around(in, 0, 1), jitter = around(in, 0, 0.5);
    Mesh mesh;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) {
            const auto corner = [&](int a, int b) {
                const double x = (a + jitter * around(in, 0, 1)) / 4.0 - 1.0;
                const double y = (b + jitter * around(in, 0, 1)) / 2.0 - 1.0;
                return center + size * (x * u + y * v + bend * (x * x + y * y) * normal);
            };
            const glm::dvec3 p00 = corner(i, j), p10 = corner(i + 1, j), p01 = corner(i, j + 1),
                             p11 = corner(i + 1, j + 1);
            for (const auto& triangle : {std::array{p00, p10, p11}, std::array{p00, p11, p01}})
                for (const glm::dvec3& q : triangle) {
                    mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
                    glm::vec3 p(q);
                    if (in.ConsumeIntegralInRange(0, 63) == 63)
                        p[in.ConsumeIntegralInRange(0, 2)] = hostile(in);
                    mesh.positions.push_back(p);
                }
        }
    return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const Mesh mesh = patch(in);

    Camera camera;
    camera.eye = {around(in, 0, 6), around(in, 0, 6), around(in, 6, 10)};
    camera.target = {around(in, 0, 6), around(in, 0, 6), around(in, 0, 10)};
    camera.near = std::pow(10.0, around(in, -1, 4));
    camera.far = camera.near + std::pow(10.0, around(in, 1.5, 4));
    camera.fovy_degrees = around(in, 60, 59);
    camera.reversed_z = in.ConsumeBool();
    camera.infinite_far = in.ConsumeBool();
    if (in.ConsumeBool()) {
        camera.projection = Camera::Projection::Orthographic;
        camera.ortho_height = std::pow(10.0, around(in, 0.5, 3));
    }
    // What the renderer refuses (validate in renderer.cpp).
    if (glm::length(camera.target - camera.eye) == 0.0 ||
        glm::length(glm::cross(camera.target - camera.eye, camera.up)) == 0.0)
        return 0;
    const int width = in.ConsumeIntegralInRange(64, 16384);
    const int height = in.ConsumeIntegralInRange(64, 16384);
    glm::mat4 model(1.0f);
    for (int k = 0; k < 4; ++k)
        if (in.ConsumeBool()) model[in.ConsumeIntegralInRange(0, 3)][k] = float(around(in, 0, 3));

    ClipSettings clip;
    clip.depth_range = camera.clip_depth_range();
    clip.guard_x = static_cast<float>(kGuardBand / (0.5 * width));
    clip.guard_y = static_cast<float>(kGuardBand / (0.5 * height));
    SetupSettings setup;
    setup.viewport = {width, height};
    setup.depth_range = camera.clip_depth_range();
    setup.cull = in.ConsumeBool() ? CullMode::Front : CullMode::Back;
    setup.front_face = in.ConsumeBool() ? FrontFace::Clockwise : FrontFace::CounterClockwise;
    const glm::mat4 mvp = camera.view_projection(double(width) / double(height)) * model;

    const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
    if (bounds.size() != 1 || !cluster_is_culled(make_cluster_view(mvp, clip, setup), bounds[0]))
        return 0;
    std::vector<ScreenVertex> screen(mesh.positions.size());
    std::vector<std::uint32_t> outcode(mesh.positions.size());
    VertexJob job;
    job.positions = mesh.positions.data();
    job.count = mesh.positions.size();
    job.mvp = mvp;
    job.clip = clip;
    job.setup = setup;
    job.screen_out = screen.data();
    job.outcode_out = outcode.data();
    transform_vertices_scalar(job);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const std::uint32_t* i = &mesh.indices[3 * t];
        TriangleBounds box;
        if ((outcode[i[0]] | outcode[i[1]] | outcode[i[2]]) != 0 ||
            classify_triangle(screen[i[0]], screen[i[1]], screen[i[2]], setup, box) !=
                SetupResult::Culled) {
            std::fprintf(stderr,
                         "zraster fuzz invariant broken: cluster culled, but triangle %zu is "
                         "not culled by the exact path\n",
                         t);
            std::abort();
        }
    }
    return 0;
}
