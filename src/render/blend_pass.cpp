// See blend_pass.hpp.
#include "render/blend_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "render/shade_fragment.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

constexpr std::uint32_t kNoFragment = 0xffffffffu;

float unit_clamp(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0)
}

// v / 255 for each 8-bit value v (a division per channel per fragment, looked up).
using UnormTable = std::array<float, 256>;
const UnormTable& unorm_table() {
    static const UnormTable table = [] {
        UnormTable t{};
        for (int v = 0; v < 256; ++v) t[std::size_t(v)] = float(v) / 255.0f;
        return t;
    }();
    return table;
}

std::uint32_t pack_rgba8(const glm::vec3& c) {
    return std::uint32_t(to_unorm8(c.x)) | std::uint32_t(to_unorm8(c.y)) << 8 |
           std::uint32_t(to_unorm8(c.z)) << 16 | 0xff000000u;
}

// Whether `a` is composited before `b` at the same pixel: farther first (for GREATER tests a
// smaller stored depth is farther), then a total order on content and ids, so that equal
// depths composite the same whatever the submission order.
struct FartherFirst {
    bool greater_is_nearer;
    bool operator()(const BlendFragment& a, const BlendFragment& b) const {
        if (a.depth != b.depth) return greater_is_nearer ? a.depth < b.depth : a.depth > b.depth;
        if (a.alpha != b.alpha) return a.alpha < b.alpha;
        if (a.rgba != b.rgba) return a.rgba < b.rgba;
        if (a.instance != b.instance) return a.instance < b.instance;
        return a.primitive < b.primitive;
    }
};

// The colors of a triangle's fragments lit by the SIMD Phong shader (the scalar twin without
// SIMD), a batch at a time: the values the deferred pass gives an opaque pixel of it.
class PhongFragments {
  public:
    PhongFragments(const PhongConstants& constants, const CornerAttributes& corners,
                   const glm::vec3* piece, bool simd, std::vector<BlendFragment>& fragments)
        : constants_(constants),
          corners_(corners),
          piece_(piece),
          simd_(simd),
          fragments_(fragments) {
        batch_.count = 0;
    }
    // The fragment just appended, at barycentrics (b1, b2) of the piece.
    void add(float b1, float b2) {
        const glm::vec3 w = interpolation_weights(piece_, b1, b2);
        const glm::vec3 n = interpolate_corners(corners_.normal, w);
        const glm::vec3 p = interpolate_corners(corners_.world, w);
        const int i = batch_.count++;
        batch_.nx[i] = n.x;
        batch_.ny[i] = n.y;
        batch_.nz[i] = n.z;
        batch_.px[i] = p.x;
        batch_.py[i] = p.y;
        batch_.pz[i] = p.z;
        batch_.flip[i] = (corners_.tag & kShadeFlip) != 0 ? ~0u : 0u;
        index_[i] = std::uint32_t(fragments_.size() - 1);
        if (batch_.count == kShadeBatch) flush();
    }
    void flush() {
        if (batch_.count == 0) return;
        if (simd_)
            shade_phong_batch(constants_, batch_);
        else
            shade_phong_batch_scalar(constants_, batch_);
        for (int i = 0; i < batch_.count; ++i) fragments_[index_[i]].rgba = batch_rgba(batch_, i);
        batch_.count = 0;
    }

  private:
    const PhongConstants& constants_;
    const CornerAttributes& corners_;
    const glm::vec3* piece_;
    bool simd_;
    std::vector<BlendFragment>& fragments_;
    PhongBatch batch_;
    std::uint32_t index_[kShadeBatch];
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
        const FrameInstance& fi = frame.instances[ref.instance];
        ShadingTriangle shading;
        prepare_shading_triangle(frame, chunk, ref, shading);
        CornerAttributes corners;
        corner_attributes(frame, ref, corners);
        const glm::vec3* piece = ref.piece == TriangleRef::kNotClipped
                                     ? nullptr
                                     : chunk.pieces[ref.piece].weights.data();
        std::optional<PhongFragments> phong;
        if (corners.tag != 0)
            phong.emplace(frame.phong_constants[std::size_t(fi.phong_kernel)], corners, piece,
                          options.simd, fragments);
        // The alpha of a material without alpha textures is its opacity everywhere.
        const float constant_alpha =
            fi.alpha_textured ? -1.0f : unit_clamp(fragment_alpha(frame, shading, 0, 0, 0, 0));
        if (constant_alpha == 0.0f) continue;
        for_each_covered_pixel(
            blended.setup, tile.x0, tile.y0, tile.x1, tile.y1, [&](int px, int py) {
                const std::size_t at =
                    std::size_t(py - tile.y0) * kTileStride + std::size_t(px - tile.x0);
                const float z = depth_at(blended.setup, px, py);
                const float code = tile.codec.format() == DepthFormat::D32F
                                       ? z
                                       : static_cast<float>(tile.codec.encode(z));
                if (options.depth_test && !DepthBuffer::passes(code, tile.depth[at], tile.compare))
                    return;
                const glm::vec3 b = barycentrics(blended.setup, px, py, options.interpolation);
                const float alpha =
                    constant_alpha >= 0.0f
                        ? constant_alpha
                        : unit_clamp(fragment_alpha(frame, shading, b.y, b.z, px, py));
                if (alpha == 0.0f) return;
                fragments.push_back(
                    BlendFragment{std::uint32_t((py - tile.y0) * width + (px - tile.x0)),
                                  kNoFragment, code, alpha, 0, fi.scene_instance, ref.primitive});
                if (phong)
                    phong->add(b.y, b.z);
                else
                    fragments.back().rgba =
                        pack_rgba8(shade_fragment(frame, shading, b.y, b.z, px, py, false).color);
            });
        if (phong) phong->flush();
    }
    BlendCounts counts;
    counts.fragments = fragments.size();
    if (fragments.empty()) return counts;

    // Each pixel's fragments as a list (the A-buffer's way: no sort of the whole tile), then
    // each list in compositing order.
    std::vector<std::uint32_t>& head = scratch.head;
    head.assign(std::size_t(width) * std::size_t(tile.y1 - tile.y0), kNoFragment);
    for (std::uint32_t f = 0; f < fragments.size(); ++f) {
        fragments[f].next = head[fragments[f].pixel];
        head[fragments[f].pixel] = f;
    }
    const CompareFunc compare = tile.compare;
    const FartherFirst farther{compare == CompareFunc::Greater ||
                               compare == CompareFunc::GreaterEqual};
    const auto before = [&](std::uint32_t a, std::uint32_t b) {
        return farther(fragments[a], fragments[b]);
    };
    std::vector<std::uint32_t>& list = scratch.list;
    const TargetViews& t = tile.targets;
    for (std::size_t pixel = 0; pixel < head.size(); ++pixel) {
        if (head[pixel] == kNoFragment) continue;
        list.clear();
        for (std::uint32_t f = head[pixel]; f != kNoFragment; f = fragments[f].next)
            list.push_back(f);
        // (Lists are short: an insertion sort.)
        for (std::size_t i = 1; i < list.size(); ++i)
            for (std::size_t j = i; j > 0 && before(list[j], list[j - 1]); --j)
                std::swap(list[j], list[j - 1]);
        const int px = tile.x0 + int(pixel % std::size_t(width));
        const int py = tile.y0 + int(pixel / std::size_t(width));
        std::uint8_t* rgba = target_row(t.color, t.color_pitch, py) + std::size_t(px) * 4;
        const UnormTable& unorm = unorm_table();
        glm::vec3 c(unorm[rgba[0]], unorm[rgba[1]], unorm[rgba[2]]);
        for (const std::uint32_t index : list) {
            const BlendFragment& f = fragments[index];
            const glm::vec3 color(unorm[f.rgba & 0xff], unorm[(f.rgba >> 8) & 0xff],
                                  unorm[(f.rgba >> 16) & 0xff]);
            c = color * f.alpha + c * (1.0f - f.alpha);
        }
        rgba[0] = to_unorm8(c.x);
        rgba[1] = to_unorm8(c.y);
        rgba[2] = to_unorm8(c.z);
        ++counts.pixels;
    }
    return counts;
}

}  // namespace zraster::detail
