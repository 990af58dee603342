// Finishing a tile (tile_resolve.hpp).
#include "render/tile_resolve.hpp"

#include <algorithm>
#include <cstring>

#include "raster/tile_layout.hpp"
#include "render/shade_kernel.hpp"

namespace zraster::detail {
namespace {

// What the deferred pass needs of the triangle of the last pixel: consecutive pixels mostly
// share one, so the lookups (chunk, ref, instance: cache misses on dense meshes) are done once
// per run.
struct TriangleRun {
    std::uint32_t id = kNoTriangle;
    const Chunk* chunk = nullptr;
    const TriangleRef* ref = nullptr;
    std::int32_t instance_id = -1, primitive_id = -1;

    void load(const Frame& frame, std::uint32_t triangle) {
        id = triangle;
        chunk = &frame.chunks[reference_chunk(triangle)];
        ref = &chunk->refs[reference_local(triangle)];
        instance_id = static_cast<std::int32_t>(frame.instances[ref->instance].scene_instance);
        primitive_id = static_cast<std::int32_t>(ref->primitive);
    }
};

// The normal target's value at a tagged pixel: what shade_fragment gives a Phong fragment, from
// the normal the kernel interpolated as shade_fragment interpolates it.
glm::vec3 tagged_normal(const TileBuffers& tile, std::size_t at) {
    const glm::vec3 n = unit_normal(glm::vec3(tile.nx[at], tile.ny[at], tile.nz[at]));
    return (tile.shade_tag[at] & kShadeFlip) != 0 ? -n : n;
}

}  // namespace

// The targets of a tile where nothing was drawn, from rows of the cleared values.
void clear_tile_targets(const TileContext& c, const float* clear_row,
                        const std::uint32_t* background_row) {
    const TargetViews& t = c.plan.targets.views;
    const auto n = static_cast<std::size_t>(c.x1 - c.x0);
    const auto x0 = static_cast<std::size_t>(c.x0);
    for (int py = c.y0; py < c.y1; ++py) {
        if (t.depth != nullptr)
            c.plan.write_row(target_row(t.depth, t.depth_pitch, py) + x0, clear_row,
                             n * sizeof(float));
        if (t.color != nullptr)
            c.plan.write_row(target_row(t.color, t.color_pitch, py) + x0 * 4, background_row,
                             n * 4);
        if (t.normal != nullptr)
            std::fill_n(target_row(t.normal, t.normal_pitch, py) + x0, n, glm::vec3(0.0f));
        if (t.instance_id != nullptr)
            std::fill_n(target_row(t.instance_id, t.instance_id_pitch, py) + x0, n, -1);
        if (t.primitive_id != nullptr)
            std::fill_n(target_row(t.primitive_id, t.primitive_id_pitch, py) + x0, n, -1);
    }
}

// Zeroes a tile's rows of the coverage counts (they are counted up as fragments pass).
void clear_tile_counts(const TileContext& c) {
    const TargetViews& t = c.plan.targets.views;
    const auto n = static_cast<std::size_t>(c.x1 - c.x0);
    const auto x0 = static_cast<std::size_t>(c.x0);
    for (int py = c.y0; py < c.y1; ++py) {
        if (t.front_hits != nullptr)
            std::fill_n(target_row(t.front_hits, t.front_hits_pitch, py) + x0, n, 0u);
        if (t.back_hits != nullptr)
            std::fill_n(target_row(t.back_hits, t.back_hits_pitch, py) + x0, n, 0u);
    }
}

std::uint64_t resolve_tile(const TileContext& c, const TileBuffers& tile,
                           const std::uint32_t* background_row) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const TargetViews& t = plan.targets.views;
    const bool d32 = plan.codec.format() == DepthFormat::D32F;
    const bool want_normal = plan.targets.normal, want_ids = plan.targets.ids;
    const bool want_color = plan.targets.color;
    const bool shade_now = plan.resolves_then_shades();
    const bool tagged = plan.tagged();
    const std::uint32_t background = background_row[0];
    // Pixel by pixel only where something needs it.
    const bool per_pixel = want_ids || (shade_now && (!tagged || c.counts.untagged)) ||
                           (want_color && !tagged) || want_normal;
    ShadingTriangle cache;
    std::uint32_t cached_id = kNoTriangle;
    TriangleRun run;
    std::uint64_t shaded = 0;
    const int n = c.x1 - c.x0;
    std::uint32_t row_rgba[kTileStride];
    for (int py = c.y0; py < c.y1; ++py) {
        const std::size_t at_row = tile_index(0, py - c.y0);
        // The rows of the targets (null where not wanted).
        const auto row = [py](auto* first_row, std::size_t pitch) {
            return first_row != nullptr ? target_row(first_row, pitch, py) : nullptr;
        };
        std::uint8_t* const color_row = row(t.color, t.color_pitch);
        glm::vec3* const normal_row = row(t.normal, t.normal_pitch);
        std::int32_t* const instance_row = row(t.instance_id, t.instance_id_pitch);
        std::int32_t* const primitive_row = row(t.primitive_id, t.primitive_id_pitch);
        if (t.depth != nullptr) {
            float* const depth_row = target_row(t.depth, t.depth_pitch, py);
            if (d32) {
                plan.write_row(depth_row + c.x0, tile.depth + at_row,
                               std::size_t(n) * sizeof(float));
            } else {
                for (int i = 0; i < n; ++i)
                    depth_row[c.x0 + i] = plan.codec.decode(
                        static_cast<std::uint32_t>(tile.depth[at_row + std::size_t(i)]));
            }
        }
        if (plan.shading == ShadingPath::TaggedForward) {  // lit as they passed
            plan.write_row(color_row + std::size_t(c.x0) * 4, tile.color + at_row,
                           std::size_t(n) * sizeof(std::uint32_t));
        } else if (tagged && want_color) {
            // (A copy, not a fill: GCC at -O2 fills element by element.)
            std::memcpy(row_rgba, background_row, std::size_t(n) * sizeof(std::uint32_t));
            shaded += std::uint64_t(
                shade_tagged_row(frame.phong_constants.data(), tile, at_row, n, row_rgba));
            plan.write_row(color_row + std::size_t(c.x0) * 4, row_rgba,
                           std::size_t(n) * sizeof(std::uint32_t));
        }
        if (!per_pixel) continue;
        for (int px = c.x0; px < c.x1; ++px) {
            const std::size_t at = at_row + std::size_t(px - c.x0);
            const std::uint32_t id = tile.ref[at];
            if (id == kNoTriangle) {
                if (want_color && !tagged)
                    std::memcpy(color_row + std::size_t(px) * 4, &background, 4);
                if (want_normal) normal_row[px] = glm::vec3(0.0f);
                if (instance_row != nullptr) instance_row[px] = -1;
                if (primitive_row != nullptr) primitive_row[px] = -1;
                continue;
            }
            if (tagged && tile.shade_tag[at] != 0) {
                if (want_normal) normal_row[px] = tagged_normal(tile, at);
                shaded += !want_color;  // (counted by shade_tagged_row otherwise)
                if (!want_ids) continue;
            }
            if (id != run.id) run.load(frame, id);
            if (instance_row != nullptr) instance_row[px] = run.instance_id;
            if (primitive_row != nullptr) primitive_row[px] = run.primitive_id;
            if (!shade_now || (tagged && tile.shade_tag[at] != 0)) continue;
            ++shaded;
            if (id != cached_id) {
                prepare_shading_triangle(frame, *run.chunk, *run.ref, cache);
                cached_id = id;
            }
            write_shaded(
                plan, shade_fragment(frame, cache, tile.b1[at], tile.b2[at], px, py, want_normal),
                px, py);
        }
    }
    return shaded;
}

}  // namespace zraster::detail
