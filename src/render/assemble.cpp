// Primitive assembly: triangles from indices, trivial accept/reject by outcodes, homogeneous
// clipping of the rest, back-face culling and a pixel-coverage test on the snapped vertices
// (most triangles of a dense mesh cover no pixel center and stop here). Runs in parallel over
// chunks of triangles (each keeps its own refs and counts them per tile as it makes them), then
// bins them into screen tiles (binning.hpp).
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

#include <zraster/error.hpp>

#include "render/binning.hpp"
#include "render/classify_kernel.hpp"
#include "render/frame.hpp"
#include "render/shade_fragment.hpp"
#include "render/vertex_kernel.hpp"
#include "render/word_hash.hpp"

namespace zraster::detail {
namespace {

// Tests a triangle of snapped vertices and, if it covers a pixel center, appends its ref.
void emit(const Frame& frame, TriangleRef ref, const ScreenVertex& v0, const ScreenVertex& v1,
          const ScreenVertex& v2, Chunk& chunk) {
    TriangleBounds setup;
    switch (classify_triangle(v0, v1, v2, instance_setup(frame, frame.instances[ref.instance]),
                              setup)) {
        case SetupResult::Visible:
            break;
        case SetupResult::Degenerate:
            ++chunk.stats.triangles_degenerate;
            return;
        case SetupResult::Culled:
            ++chunk.stats.triangles_backface_culled;
            return;
        case SetupResult::NoCoverage:
            ++chunk.stats.triangles_no_coverage;
            return;
    }
    ref.front_facing = setup.front_facing;
    ref.tile_x0 = static_cast<std::uint8_t>(setup.min_x / kTileSize);
    ref.tile_y0 = static_cast<std::uint8_t>(setup.min_y / kTileSize);
    ref.tile_x1 = static_cast<std::uint8_t>(setup.max_x / kTileSize);
    ref.tile_y1 = static_cast<std::uint8_t>(setup.max_y / kTileSize);
    ++chunk.stats.triangles_rasterized;
    count_in_bins(frame, ref, chunk);
    chunk.refs.push_back(ref);
}

void clip_and_emit(const Frame& frame, TriangleRef ref, const std::array<glm::vec4, 3>& clip,
                   std::uint32_t crossing, Chunk& chunk) {
    const RenderOptions& options = *frame.options;
    const int user_planes = frame.clip_settings.user_plane_count;
    std::array<std::array<float, 3>, kMaxUserClipPlanes> user_distances{};
    for (int p = 0; p < user_planes; ++p) {
        const glm::vec4& plane = options.clip_planes[static_cast<std::size_t>(p)];
        for (std::size_t k = 0; k < 3; ++k)
            user_distances[static_cast<std::size_t>(p)][k] =
                glm::dot(glm::vec3(plane), frame.vertices.world[ref.vertex[k]]) + plane.w;
    }
    ClippedPolygon polygon;
    clip_triangle(clip, crossing, frame.clip_settings,
                  std::span(user_distances.data(), static_cast<std::size_t>(user_planes)), polygon);
    if (polygon.count < 3) return;
    // New vertices go to the chunk; the polygon's vertices are snapped once each, so the fan's
    // pieces share exact vertices and leave no cracks between them.
    const auto base = static_cast<std::uint32_t>(chunk.extra_vertices.size());
    for (int k = 0; k < polygon.count; ++k) {
        ScreenVertex s;
        if (!to_screen(polygon.vertices[static_cast<std::size_t>(k)].position, frame.setup_settings,
                       s)) {
            ++chunk.stats.triangles_degenerate;
            chunk.extra_vertices.resize(base);
            return;
        }
        chunk.extra_vertices.push_back(s);
    }
    for (int k = 1; k + 1 < polygon.count; ++k) {
        const auto a = base, b = base + std::uint32_t(k), c = base + std::uint32_t(k + 1);
        ref.piece = static_cast<std::uint32_t>(chunk.pieces.size());
        const std::size_t before = chunk.refs.size();
        emit(frame, ref, chunk.extra_vertices[a], chunk.extra_vertices[b], chunk.extra_vertices[c],
             chunk);
        if (chunk.refs.size() != before)
            chunk.pieces.push_back({{polygon.vertices[0].weights,
                                     polygon.vertices[static_cast<std::size_t>(k)].weights,
                                     polygon.vertices[static_cast<std::size_t>(k + 1)].weights},
                                    {a, b, c}});
    }
}

// One triangle the general way: bad indices, non-finite vertices, user planes, outcodes,
// clipping.
void assemble_triangle(const Frame& frame, std::uint32_t instance, std::size_t t, Chunk& chunk) {
    const FrameInstance& fi = frame.instances[instance];
    const FrameMesh& mesh = *fi.mesh;
    const RenderOptions& options = *frame.options;
    const FrameVertices& vertices = frame.vertices;
    const int user_planes = frame.clip_settings.user_plane_count;
    const auto vertex_total = static_cast<std::uint32_t>(mesh.vertex_count());
    TriangleRef ref;
    ref.instance = instance;
    ref.primitive = static_cast<std::uint32_t>(t);
    std::array<std::uint32_t, 3> code{}, local{};
    bool valid = true, finite = true;
    for (std::size_t k = 0; k < 3; ++k) {
        local[k] = mesh.index(3 * t + k);
        valid &= local[k] < vertex_total;
        const std::uint32_t global = fi.first_vertex + (local[k] < vertex_total ? local[k] : 0);
        ref.vertex[k] = global;
        code[k] = vertices.outcode[global];
        finite &= code[k] != kNonFinite;
    }
    if (!valid) {  // the renderer refuses the scene after this stage (check_indices)
        chunk.bad_index_instance = std::min(chunk.bad_index_instance, instance);
        return;
    }
    if (!finite) {  // a NaN/Inf vertex: nothing sensible to draw
        ++chunk.stats.triangles_non_finite;
        return;
    }
    for (int p = 0; p < user_planes; ++p) {
        const glm::vec4& plane = options.clip_planes[static_cast<std::size_t>(p)];
        for (std::size_t k = 0; k < 3; ++k)
            if (!(glm::dot(glm::vec3(plane), vertices.world[ref.vertex[k]]) + plane.w >= 0.0f))
                code[k] |= kClipUser0 << p;
    }
    if (code[0] & code[1] & code[2]) {
        ++chunk.stats.triangles_trivially_rejected;
        return;
    }
    const std::uint32_t crossing = code[0] | code[1] | code[2];
    if (crossing == 0) {
        emit(frame, ref, vertices.screen[ref.vertex[0]], vertices.screen[ref.vertex[1]],
             vertices.screen[ref.vertex[2]], chunk);
        return;
    }
    ++chunk.stats.triangles_clipped;
    // The clip positions the vertex stage computed (and did not keep), bit for bit.
    const auto clip = [&](std::size_t k) { return clip_position(fi.mvp, mesh.position(local[k])); };
    clip_and_emit(frame, ref, {clip(0), clip(1), clip(2)}, crossing, chunk);
}

// Triangles [first, end) of an instance with the batch classifier (no user clip planes).
void classify_range(const Frame& frame, std::uint32_t instance, const ClassifyInput& in,
                    std::size_t first, std::size_t end, ClassifyOutput& out, Chunk& chunk) {
    const FrameInstance& fi = frame.instances[instance];
    for (std::size_t t = first; t < end; t += ClassifyOutput::kMaxBatch) {
        const std::size_t n = std::min(ClassifyOutput::kMaxBatch, end - t);
        if (frame.options->simd)
            classify_triangles(in, t, n, out);
        else
            classify_triangles_scalar(in, t, n, out);
        for (std::uint32_t k = 0; k < out.count; ++k) {
            if (out.flags[k] & ClassifyOutput::kSlow) {
                assemble_triangle(frame, instance, out.triangle[k], chunk);
                continue;
            }
            // Written in place: a ref built on the stack in narrow stores and copied out in
            // wide loads stalls on store forwarding, twice per triangle.
            TriangleRef& ref = chunk.refs.emplace_back();
            ref.instance = instance;
            ref.primitive = out.triangle[k];
            const std::uint32_t* corner =
                in.indices + 3 * (std::size_t{out.triangle[k]} - in.first_triangle);
            for (std::size_t c = 0; c < 3; ++c) ref.vertex[c] = fi.first_vertex + corner[c];
            ref.front_facing = (out.flags[k] & ClassifyOutput::kFront) != 0;
            ref.tile_x0 = static_cast<std::uint8_t>(out.min_x[k] / kTileSize);
            ref.tile_y0 = static_cast<std::uint8_t>(out.min_y[k] / kTileSize);
            ref.tile_x1 = static_cast<std::uint8_t>(out.max_x[k] / kTileSize);
            ref.tile_y1 = static_cast<std::uint8_t>(out.max_y[k] / kTileSize);
            ++chunk.stats.triangles_rasterized;
            count_in_bins(frame, ref, chunk);
        }
    }
}

void process_instance_range(const Frame& frame, std::uint32_t instance, std::size_t first,
                            std::size_t end, Chunk& chunk, ClassifyOutput& out) {
    const FrameInstance& fi = frame.instances[instance];
    const FrameMesh& mesh = *fi.mesh;
    const FrameVertices& vertices = frame.vertices;
    // The batch classifier computes frame vertex indices in 32-bit lanes.
    const bool batch = frame.clip_settings.user_plane_count == 0 &&
                       vertices.screen.size() < (std::size_t{1} << 31);
    if (!batch) {
        for (std::size_t t = first; t < end; ++t) assemble_triangle(frame, instance, t, chunk);
        return;
    }
    ClassifyInput in;
    if (mesh.indices != nullptr) {
        in.indices = mesh.indices;
        in.triangle_total = mesh.triangle_count();
    } else {  // 16-bit: the range's indices widened, in the chunk's kept scratch
        chunk.widened_indices.resize(3 * (end - first));
        widen_indices(mesh.view->indices, 3 * first, 3 * (end - first),
                      chunk.widened_indices.data());
        in.indices = chunk.widened_indices.data();
        in.first_triangle = first;
        in.triangle_total = end;
    }
    in.vertex_total = static_cast<std::uint32_t>(mesh.vertex_count());
    in.first_vertex = fi.first_vertex;
    in.screen = vertices.screen.data();
    in.settings = instance_setup(frame, fi);
    out.degenerate = out.culled = out.no_coverage = 0;
    // Whole clusters inside the range that their bounds prove culled are skipped (counted as
    // culled, as the classifier would); the triangles between them are classified.
    std::size_t run = first;
    if (fi.clusters != nullptr) {
        // The clusters that lie wholly inside the range, tested all at once.
        const std::size_t triangles = mesh.triangle_count();
        const std::size_t first_cluster = (first + kClusterTriangles - 1) / kClusterTriangles;
        const std::size_t end_cluster =
            end == triangles ? cluster_count(triangles) : end / kClusterTriangles;
        const std::size_t clusters = std::max(first_cluster, end_cluster) - first_cluster;
        const ClusterArrays& arrays = fi.clusters->arrays;
        // The vertex stage's verdicts, or this range's own.
        const std::uint8_t* culled =
            fi.culled_clusters != nullptr ? fi.culled_clusters + first_cluster : nullptr;
        if (culled == nullptr) {
            std::vector<std::uint8_t>& verdicts = chunk.cluster_verdicts;
            verdicts.resize(clusters);
            (frame.options->simd ? clusters_culled : clusters_culled_scalar)(
                fi.cluster_view, arrays, first_cluster, clusters, verdicts.data());
            culled = verdicts.data();
        }
        for (std::size_t c = first_cluster; c < first_cluster + clusters; ++c) {
            if (!culled[c - first_cluster]) continue;
            const std::size_t lo = c * kClusterTriangles;
            const std::size_t hi = std::min(lo + kClusterTriangles, triangles);
            // The bounds hold for the indices they were built from: check those are still here.
            if (!fi.cluster_indices_checked && !frame.options->static_meshes &&
                cluster_index_hash(*mesh.view, c) != arrays.index_hash[c]) {
                fi.clusters->stale = true;
                continue;
            }
            classify_range(frame, instance, in, run, lo, out, chunk);
            run = hi;
            chunk.stats.triangles_backface_culled += hi - lo;
            ++chunk.stats.clusters_culled;
        }
    }
    classify_range(frame, instance, in, run, end, out, chunk);
    chunk.stats.triangles_degenerate += out.degenerate;
    chunk.stats.triangles_backface_culled += out.culled;
    chunk.stats.triangles_no_coverage += out.no_coverage;
}

// `out`: the calling thread's slot's (SlotScratch::classify).
void process_chunk(const Frame& frame, Chunk& chunk, ClassifyOutput& out) {
    const std::vector<std::size_t>& prefix = frame.instance_first_triangle;
    chunk.refs.reserve((chunk.end_triangle - chunk.first_triangle) / 2);
    chunk.bin_counts.assign(std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y), 0);
    auto i = static_cast<std::uint32_t>(
        std::upper_bound(prefix.begin(), prefix.end(), chunk.first_triangle) - prefix.begin() - 1);
    for (std::size_t g = chunk.first_triangle; g < chunk.end_triangle; ++i) {
        const std::size_t end = std::min(chunk.end_triangle, prefix[i + 1]);
        process_instance_range(frame, i, g - prefix[i], end - prefix[i], chunk, out);
        g = end;
    }
    chunk.stats.triangles_in = chunk.end_triangle - chunk.first_triangle;
    // The size of the chunk's bin runs (write_bins' scratch is sized for the largest chunk).
    std::size_t bytes = 0;
    for (const std::uint32_t n : chunk.bin_counts) bytes += whole_lines(n * frame.bin_record_bytes);
    chunk.bin_bytes = bytes;
}

}  // namespace

void assemble_and_bin(Frame& frame, RenderStats& stats) {
    std::size_t total = 0;
    frame.instance_first_triangle.assign(1, 0);
    for (const FrameInstance& fi : frame.instances) {
        total += fi.mesh->triangle_count();
        frame.instance_first_triangle.push_back(total);
    }
    // At most kMaxChunks chunks (the chunk is the top bits of a pixel's triangle reference,
    // tile_layout.hpp), of at least kMinChunkTriangles triangles.
    if (total > kMaxFrameTriangles)
        throw InputError(
            "", "more than " + std::to_string(kMaxFrameTriangles) + " triangles in one frame");
    const std::size_t chunk_triangles = std::max(kMinChunkTriangles, total / kMaxChunks + 1);
    // Chunk objects are reused from frame to frame (their arrays keep their capacity).
    frame.chunks.resize((total + chunk_triangles - 1) / chunk_triangles);
    for (std::size_t c = 0; c < frame.chunks.size(); ++c) {
        frame.chunks[c].first_triangle = c * chunk_triangles;
        frame.chunks[c].end_triangle = std::min(total, (c + 1) * chunk_triangles);
    }
    const auto start = std::chrono::steady_clock::now();
    frame.bin_record_bytes = bin_record_bytes(frame.tagged_shading);
    tbb::parallel_for(std::size_t{0}, frame.chunks.size(), [&](std::size_t c) {
        process_chunk(frame, frame.chunks[c], frame.slot().classify);
    });
    const auto assembled = std::chrono::steady_clock::now();
    stats.assembly_ms = std::chrono::duration<double, std::milli>(assembled - start).count();
    bin_triangles(frame);
    stats.binning_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - assembled)
            .count();
    for (const Chunk& c : frame.chunks) {
        stats.triangles_in += c.stats.triangles_in;
        stats.triangles_non_finite += c.stats.triangles_non_finite;
        stats.triangles_trivially_rejected += c.stats.triangles_trivially_rejected;
        stats.triangles_clipped += c.stats.triangles_clipped;
        stats.triangles_backface_culled += c.stats.triangles_backface_culled;
        stats.triangles_degenerate += c.stats.triangles_degenerate;
        stats.triangles_no_coverage += c.stats.triangles_no_coverage;
        stats.triangles_rasterized += c.stats.triangles_rasterized;
        stats.clusters_culled += c.stats.clusters_culled;
    }
}

}  // namespace zraster::detail
