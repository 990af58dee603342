// Primitive assembly: triangles from indices, trivial accept/reject by outcodes, homogeneous
// clipping of the rest, and triangle setup (which also culls back faces in screen space).
// Runs in parallel over chunks of triangles; chunks are concatenated in submission order.
#include <tbb/parallel_for.h>

#include <cmath>
#include <vector>

#include "render/frame.hpp"

namespace zraster::detail {
namespace {

struct Chunk {
    std::uint32_t instance;
    std::size_t first_triangle, end_triangle;
};

struct ChunkOutput {
    std::vector<RasterTriangle> triangles;
    RenderStats stats;
};

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

LightTerms flat_terms(const Frame& frame, const FrameInstance& fi,
                      const std::array<std::uint32_t, 3>& idx, bool front_facing) {
    const glm::vec3& a = frame.vertices.world[idx[0]];
    const glm::vec3& b = frame.vertices.world[idx[1]];
    const glm::vec3& c = frame.vertices.world[idx[2]];
    glm::vec3 n = glm::cross(b - a, c - a);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
    if (!front_facing && frame.options->two_sided_lighting) n = -n;
    const glm::vec3 centroid = (a + b + c) / 3.0f;
    return evaluate_lighting(frame.options->lighting, *fi.material, centroid, n, frame.eye,
                             frame.view_axis);
}

void emit(const Frame& frame, const FrameInstance& fi, RasterTriangle& rt,
          const std::array<glm::vec4, 3>& clip, ChunkOutput& out) {
    switch (setup_triangle(clip, frame.setup_settings, rt.setup)) {
        case SetupResult::Visible:
            if (fi.shading == ShadingMode::Flat)
                rt.flat = flat_terms(frame, fi, rt.vertex, rt.setup.front_facing);
            ++out.stats.triangles_rasterized;
            out.triangles.push_back(rt);
            break;
        case SetupResult::Degenerate: ++out.stats.triangles_degenerate; break;
        case SetupResult::Culled: ++out.stats.triangles_backface_culled; break;
        case SetupResult::NoCoverage: ++out.stats.triangles_no_coverage; break;
    }
}

void process_chunk(const Frame& frame, const Chunk& chunk, ChunkOutput& out) {
    const FrameInstance& fi = frame.instances[chunk.instance];
    const Mesh& mesh = *fi.mesh;
    const RenderOptions& options = *frame.options;
    const int user_planes = frame.clip_settings.user_plane_count;
    const auto vertex_total = static_cast<std::uint32_t>(mesh.positions.size());
    ClippedPolygon polygon;

    for (std::size_t t = chunk.first_triangle; t < chunk.end_triangle; ++t) {
        ++out.stats.triangles_in;
        RasterTriangle rt;
        rt.instance = chunk.instance;
        rt.primitive = static_cast<std::uint32_t>(t);
        std::array<glm::vec4, 3> clip;
        bool valid = true;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t local = mesh.indices[3 * t + k];
            if (local >= vertex_total) valid = false;  // the loaders reject this; be safe
            rt.vertex[k] = fi.first_vertex + (local < vertex_total ? local : 0);
            clip[k] = frame.vertices.clip[rt.vertex[k]];
            valid = valid && finite(clip[k]);
        }
        if (!valid) {
            ++out.stats.triangles_non_finite;
            continue;
        }

        std::array<std::array<float, 3>, kMaxUserClipPlanes> user_distances{};
        std::uint32_t codes[3];
        for (std::size_t k = 0; k < 3; ++k) {
            float d[kMaxUserClipPlanes] = {};
            for (int p = 0; p < user_planes; ++p) {
                const glm::vec4& plane = options.clip_planes[static_cast<std::size_t>(p)];
                d[p] = glm::dot(glm::vec3(plane), frame.vertices.world[rt.vertex[k]]) + plane.w;
                user_distances[static_cast<std::size_t>(p)][k] = d[p];
            }
            codes[k] = clip_outcode(clip[k], frame.clip_settings,
                                    std::span<const float>(d, static_cast<std::size_t>(user_planes)));
        }
        if (codes[0] & codes[1] & codes[2]) {
            ++out.stats.triangles_trivially_rejected;
            continue;
        }
        const std::uint32_t crossing = codes[0] | codes[1] | codes[2];
        if (crossing == 0) {
            emit(frame, fi, rt, clip, out);
            continue;
        }

        ++out.stats.triangles_clipped;
        clip_triangle(clip, crossing, frame.clip_settings,
                      std::span(user_distances.data(), static_cast<std::size_t>(user_planes)),
                      polygon);
        // Fan-triangulate the convex polygon; its pieces share exact vertices, so no cracks.
        for (int k = 1; k + 1 < polygon.count; ++k) {
            const ClipVertex& a = polygon.vertices[0];
            const ClipVertex& b = polygon.vertices[static_cast<std::size_t>(k)];
            const ClipVertex& c = polygon.vertices[static_cast<std::size_t>(k + 1)];
            rt.clipped = true;
            rt.weights = {a.weights, b.weights, c.weights};
            emit(frame, fi, rt, {a.position, b.position, c.position}, out);
        }
    }
}

}  // namespace

void assemble_and_setup(Frame& frame, RenderStats& stats) {
    constexpr std::size_t kChunkTriangles = 8192;
    std::vector<Chunk> chunks;
    for (std::uint32_t i = 0; i < frame.instances.size(); ++i) {
        const std::size_t count = frame.instances[i].mesh->triangle_count();
        for (std::size_t first = 0; first < count; first += kChunkTriangles)
            chunks.push_back({i, first, std::min(count, first + kChunkTriangles)});
    }
    std::vector<ChunkOutput> outputs(chunks.size());
    tbb::parallel_for(std::size_t{0}, chunks.size(),
                      [&](std::size_t c) { process_chunk(frame, chunks[c], outputs[c]); });

    std::size_t total = 0;
    for (const ChunkOutput& o : outputs) total += o.triangles.size();
    frame.triangles.reserve(total);
    for (ChunkOutput& o : outputs) {
        frame.triangles.insert(frame.triangles.end(), o.triangles.begin(), o.triangles.end());
        stats.triangles_in += o.stats.triangles_in;
        stats.triangles_non_finite += o.stats.triangles_non_finite;
        stats.triangles_trivially_rejected += o.stats.triangles_trivially_rejected;
        stats.triangles_clipped += o.stats.triangles_clipped;
        stats.triangles_backface_culled += o.stats.triangles_backface_culled;
        stats.triangles_degenerate += o.stats.triangles_degenerate;
        stats.triangles_no_coverage += o.stats.triangles_no_coverage;
        stats.triangles_rasterized += o.stats.triangles_rasterized;
        o = ChunkOutput{};
    }
}

}  // namespace zraster::detail
