// The blend pass's kernels (blend_pass.hpp): reading a blended triangle's fragments out of the
// visibility kernel's buffers into per-pixel slots, and compositing each pixel's slots "over"
// its color (Porter & Duff 1984), farthest first. The SIMD kernels (Google Highway, the
// instruction set picked at run time) take a vector of pixels at a time; their scalar twins a
// pixel at a time. Both make the same float operations in the same order (no FMA:
// -ffp-contract=off) and agree bit for bit (tests/render/blend_kernels_test.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "raster/visibility_kernel.hpp"

namespace zraster::detail {

// A pixel's first kBlendSlots fragments stay in slots, in the order they came; more go to a
// list (BlendSlots::more).
inline constexpr std::uint32_t kBlendSlots = 4;

// A blended fragment. `depth_key` orders depths so that a smaller key is farther (composited
// first); `source` is its triangle (an index into the tile's blended triangles).
struct BlendFragment {
    std::uint32_t depth_key = 0;
    float alpha = 0.0f;      // in (0, 1]
    std::uint32_t rgba = 0;  // shaded, RGBA8 as the color target holds it
    std::uint32_t source = 0;
};

// The sort key of a stored depth: composited farther first, so for GREATER tests (a smaller
// stored depth is farther) the depth's bits, else their complement. Stored depths are never
// negative (depth_at clamps to [0, 1] and turns -0 into +0; unorm codes are whole numbers),
// and the bits of non-negative floats order as the floats do.
inline std::uint32_t blend_depth_key(float code, bool greater_is_nearer) {
    std::uint32_t bits;
    std::memcpy(&bits, &code, 4);
    return greater_is_nearer ? bits : ~bits;
}

// Whether fragment `a` is composited before `b` at the same pixel: farther first, then a total
// order on content and ids (alpha, color, scene instance, primitive of the source triangle), so
// that equal depths composite the same whatever the submission order.
struct CompositingOrder {
    const std::uint32_t* instance;
    const std::uint32_t* primitive;
    bool operator()(const BlendFragment& a, const BlendFragment& b) const {
        if (a.depth_key != b.depth_key) return a.depth_key < b.depth_key;
        if (a.alpha != b.alpha) return a.alpha < b.alpha;
        if (a.rgba != b.rgba) return a.rgba < b.rgba;
        if (instance[a.source] != instance[b.source])
            return instance[a.source] < instance[b.source];
        return primitive[a.source] < primitive[b.source];
    }
};

// A tile's slots, layer-major (the kernels load a layer of a vector of pixels at once): layer l
// of pixel p is element l * pixels + p of each field's array.
struct BlendSlots {
    std::size_t pixels = 0;
    std::vector<std::uint32_t> count;  // per pixel: its fragments (beyond kBlendSlots: in `more`)
    std::vector<std::uint32_t> depth_key, rgba, source;
    std::vector<float> alpha;
    std::vector<std::pair<std::uint32_t, BlendFragment>> more;  // (pixel, fragment)

    void start(std::size_t tile_pixels) {
        pixels = tile_pixels;
        count.assign(pixels, 0);
        if (depth_key.size() < pixels * kBlendSlots) {
            depth_key.resize(pixels * kBlendSlots);
            rgba.resize(pixels * kBlendSlots);
            source.resize(pixels * kBlendSlots);
            alpha.resize(pixels * kBlendSlots);
        }
        more.clear();
    }
    BlendFragment slot(std::size_t pixel, std::uint32_t layer) const {
        const std::size_t at = layer * pixels + pixel;
        return {depth_key[at], alpha[at], rgba[at], source[at]};
    }
    // Appends a fragment to its pixel.
    void add(std::size_t pixel, const BlendFragment& f) {
        const std::uint32_t n = count[pixel]++;
        if (n >= kBlendSlots) {
            more.emplace_back(std::uint32_t(pixel), f);
            return;
        }
        const std::size_t at = n * pixels + pixel;
        depth_key[at] = f.depth_key;
        alpha[at] = f.alpha;
        rgba[at] = f.rgba;
        source[at] = f.source;
    }
};

// A row of a blended triangle's fragments as the visibility kernel left them (forward-lit:
// color in TileBuffers::color, depth in TileBuffers::depth, `id` in TileBuffers::ref): pixels
// [at, at + width) of `buffers`, which are pixels [pixel, pixel + width) of the slots. Each
// fragment's ref is reset to kNoTriangle and its depth restored from `opaque_depth` (same
// indexing as buffers), and the fragment appended to its pixel's slots with `alpha` and
// `source`.
struct BlendRow {
    std::size_t at;
    std::size_t pixel;
    int width;
    std::uint32_t id;
    float alpha;
    std::uint32_t source;
    bool greater_is_nearer;
};
void append_blend_row(const BlendRow& row, TileBuffers& buffers, const float* opaque_depth,
                      BlendSlots& slots);
void append_blend_row_scalar(const BlendRow& row, TileBuffers& buffers, const float* opaque_depth,
                             BlendSlots& slots);

// Composites pixels [pixel, pixel + width) of the slots (those with 1 to kBlendSlots
// fragments; the others are left alone) into `color` (their RGBA8 row in the color target,
// R in the low byte: only R, G and B are written). Per channel: c = v / 255 (v: the 8-bit
// value), then c = c_fragment * a + c * (1 - a) for each fragment in `order`, then
// round(c * 255).
void composite_blend_row(const BlendSlots& slots, std::size_t pixel, int width,
                         const CompositingOrder& order, std::uint8_t* color);
void composite_blend_row_scalar(const BlendSlots& slots, std::size_t pixel, int width,
                                const CompositingOrder& order, std::uint8_t* color);

// The arithmetic of one pixel (both paths): fragments[0, n) in compositing order.
inline float blend_channel(std::uint32_t rgba, int shift) {
    return static_cast<float>((rgba >> shift) & 0xffu) * (1.0f / 255.0f);
}
// (c stays in [0, 1]: alphas are in (0, 1] and colors come from bytes, so no clamp.)
inline std::uint8_t blend_unorm8(float c) {
    return static_cast<std::uint8_t>(static_cast<std::int32_t>(c * 255.0f + 0.5f));
}
inline void composite_fragments(const BlendFragment* fragments, std::size_t n,
                                std::uint8_t* pixel) {
    std::uint32_t dst;
    std::memcpy(&dst, pixel, 4);
    float r = blend_channel(dst, 0), g = blend_channel(dst, 8), b = blend_channel(dst, 16);
    for (std::size_t k = 0; k < n; ++k) {
        const float a = fragments[k].alpha, keep = 1.0f - a;
        r = blend_channel(fragments[k].rgba, 0) * a + r * keep;
        g = blend_channel(fragments[k].rgba, 8) * a + g * keep;
        b = blend_channel(fragments[k].rgba, 16) * a + b * keep;
    }
    pixel[0] = blend_unorm8(r);
    pixel[1] = blend_unorm8(g);
    pixel[2] = blend_unorm8(b);
}

// The scalar steps both paths share. One pixel of a row (append_blend_row):
inline void append_blend_pixel(const BlendRow& row, int i, TileBuffers& buffers,
                               const float* opaque_depth, BlendSlots& slots) {
    const std::size_t at = row.at + std::size_t(i);
    if (buffers.ref[at] != row.id) return;
    buffers.ref[at] = kNoTriangle;
    const std::uint32_t key = blend_depth_key(buffers.depth[at], row.greater_is_nearer);
    buffers.depth[at] = opaque_depth[at];
    slots.add(row.pixel + std::size_t(i), {key, row.alpha, buffers.color[at], row.source});
}
// One pixel with 1 to kBlendSlots fragments (composite_blend_row), at `color`.
inline void composite_slots_pixel(const BlendSlots& slots, std::size_t pixel,
                                  const CompositingOrder& order, std::uint8_t* color) {
    const std::uint32_t n = slots.count[pixel];
    BlendFragment f[kBlendSlots];
    for (std::uint32_t k = 0; k < n; ++k) {
        const BlendFragment moving = slots.slot(pixel, k);
        std::uint32_t j = k;
        for (; j > 0 && order(moving, f[j - 1]); --j) f[j] = f[j - 1];
        f[j] = moving;
    }
    composite_fragments(f, n, color);
}

}  // namespace zraster::detail
