// See blend_pass.hpp.
#include "render/blend_pass.hpp"

#include <algorithm>
#include <cmath>

#include "render/shade_fragment.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

float unit_clamp(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0)
}

std::uint8_t to_unorm8(float v) {
    return static_cast<std::uint8_t>(to_unorm8_int(v));
}

// Whether `a` is drawn before `b` at the same pixel: farther first (for GREATER tests, a
// smaller stored depth is farther), then a total order on content and ids, so that equal depths
// composite the same whatever the submission order.
struct FartherFirst {
    bool greater_is_nearer;
    bool operator()(const BlendFragment& a, const BlendFragment& b) const {
        if (a.pixel != b.pixel) return a.pixel < b.pixel;
        if (a.depth != b.depth) return greater_is_nearer ? a.depth < b.depth : a.depth > b.depth;
        if (a.alpha != b.alpha) return a.alpha < b.alpha;
        for (int k = 0; k < 3; ++k)
            if (a.color[k] != b.color[k]) return a.color[k] < b.color[k];
        if (a.instance != b.instance) return a.instance < b.instance;
        return a.primitive < b.primitive;
    }
};

}  // namespace

BlendCounts composite_blended(const BlendTile& tile, BlendScratch& scratch) {
    const Frame& frame = tile.frame;
    const RenderOptions& options = *frame.options;
    const int width = tile.x1 - tile.x0;
    std::vector<BlendFragment>& fragments = scratch.fragments;
    fragments.clear();
    for (const BlendTriangle& blended : scratch.triangles) {
        const Chunk& chunk = frame.chunks[blended.chunk];
        const TriangleRef& ref = chunk.refs[blended.ref];
        ShadingTriangle shading;
        prepare_shading_triangle(frame, chunk, ref, shading);
        const auto instance = frame.instances[ref.instance].scene_instance;
        for_each_covered_pixel(
            blended.setup, tile.x0, tile.y0, tile.x1, tile.y1, [&](int px, int py) {
                const std::size_t at =
                    std::size_t(py - tile.y0) * TileBuffers::kStride + std::size_t(px - tile.x0);
                const float z = depth_at(blended.setup, px, py);
                const float code = tile.codec.format() == DepthFormat::D32F
                                       ? z
                                       : static_cast<float>(tile.codec.encode(z));
                if (options.depth_test && !DepthBuffer::passes(code, tile.depth[at], tile.compare))
                    return;
                const glm::vec3 b = barycentrics(blended.setup, px, py, options.interpolation);
                const float alpha = unit_clamp(fragment_alpha(frame, shading, b.y, b.z, px, py));
                if (alpha == 0.0f) return;
                const glm::vec3 color =
                    shade_fragment(frame, shading, b.y, b.z, px, py, false).color;
                fragments.push_back(BlendFragment{
                    std::uint32_t((py - tile.y0) * width + (px - tile.x0)), code, alpha,
                    glm::vec3(unit_clamp(color.x), unit_clamp(color.y), unit_clamp(color.z)),
                    instance, ref.primitive});
            });
    }
    BlendCounts counts;
    counts.fragments = fragments.size();
    if (fragments.empty()) return counts;
    const CompareFunc compare = tile.compare;
    std::sort(
        fragments.begin(), fragments.end(),
        FartherFirst{compare == CompareFunc::Greater || compare == CompareFunc::GreaterEqual});
    const TargetViews& t = tile.targets;
    for (std::size_t i = 0; i < fragments.size();) {
        const std::uint32_t pixel = fragments[i].pixel;
        const int px = tile.x0 + int(pixel % std::uint32_t(width));
        const int py = tile.y0 + int(pixel / std::uint32_t(width));
        std::uint8_t* rgba = target_row(t.color, t.color_pitch, py) + std::size_t(px) * 4;
        glm::vec3 c(rgba[0] / 255.0f, rgba[1] / 255.0f, rgba[2] / 255.0f);
        for (; i < fragments.size() && fragments[i].pixel == pixel; ++i) {
            const BlendFragment& f = fragments[i];
            c = f.color * f.alpha + c * (1.0f - f.alpha);
        }
        rgba[0] = to_unorm8(c.x);
        rgba[1] = to_unorm8(c.y);
        rgba[2] = to_unorm8(c.z);
        ++counts.pixels;
    }
    return counts;
}

}  // namespace zraster::detail
