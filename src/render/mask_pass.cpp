// See mask_pass.hpp.
#include "render/mask_pass.hpp"

#include <algorithm>
#include <cstring>

#include "raster/tile_layout.hpp"
#include "render/shade_fragment.hpp"

namespace zraster::detail {

std::unique_ptr<TileBuffers> make_side_buffer() {
    auto side = std::make_unique<TileBuffers>();
    std::fill(std::begin(side->ref), std::end(side->ref), kNoTriangle);
    return side;
}

std::uint64_t rasterize_masked(TileContext& c, const TileTriangle& t, TileBuffers& tile,
                               TileBuffers& side) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const RenderOptions& options = *frame.options;
    const TriangleSetup& setup = t.setup;
    const int rx0 = std::max(setup.min_x, c.x0), ry0 = std::max(setup.min_y, c.y0);
    const int rx1 = std::min(setup.max_x, c.x1 - 1), ry1 = std::min(setup.max_y, c.y1 - 1);
    if (rx0 > rx1 || ry0 > ry1) return 0;
    // The tile's depths where the triangle may pass: what its fragments are tested against.
    for (int py = ry0; py <= ry1; ++py) {
        const std::size_t at = tile_index(rx0 - c.x0, py - c.y0);
        std::memcpy(side.depth + at, tile.depth + at, std::size_t(rx1 - rx0 + 1) * sizeof(float));
    }
    BlockJob job = shared_job(plan);
    job.write_depth = true;  // into `side`: the fragment's depth, written to the tile if kept
    job.attributes = true;
    job.barycentrics = true;  // what the alpha is computed from
    // (Blocks whose edges are too long for the kernel's lanes take the scalar path, which
    // alpha-tests too: the test below repeats it, to the same result.)
    draw_into_side(c, TileTriangle{t.chunk, t.ref, setup, t.id, nullptr, nullptr, nullptr}, job,
                   side);

    // The alpha test, then the writes the kernel makes for a fragment that passes.
    ShadingTriangle shading;
    prepare_shading_triangle(frame, t.chunk, t.ref, shading);
    const float cutoff = frame.instances[t.ref.instance].material->alpha_cutoff;
    const bool write_depth = options.depth_write;
    std::uint64_t kept = 0;
    for (int py = ry0; py <= ry1; ++py) {
        const std::size_t row = tile_index(0, py - c.y0) - std::size_t(c.x0);
        for (int px = rx0; px <= rx1; ++px) {
            const std::size_t at = row + std::size_t(px);
            if (side.ref[at] != t.id) continue;
            side.ref[at] = kNoTriangle;
            const float b1 = side.b1[at], b2 = side.b2[at];
            // (Alpha NaN: discarded.)
            if (!(fragment_alpha(frame, shading, b1, b2, px, py) >= cutoff)) {
                ++c.counts.alpha_discarded;
                continue;
            }
            ++kept;
            if (write_depth) tile.depth[at] = side.depth[at];
            tile.ref[at] = t.id;
            tile.b1[at] = b1;
            tile.b2[at] = b2;
            tile.shade_tag[at] = t.corners ? t.corners->tag : 0;
            if (t.corners && t.shade_constants)  // forward, as the kernel does
                tile.color[at] =
                    shade_interpolated_scalar(*t.shade_constants, *t.corners, t.piece, b1, b2);
            else if (t.corners)
                store_interpolated(*t.corners, t.piece, b1, b2, tile, at);
        }
    }
    return kept;
}

}  // namespace zraster::detail
