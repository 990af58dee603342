// The debug views' pictures (debug_view_paint.hpp).
#include "render/debug_view_paint.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "render/debug_view_mip.hpp"
#include "render/debug_view_triangles.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kUntextured{128, 128, 128};
constexpr Rgb kBackTint{230, 40, 40};
constexpr Rgb kClippedTint{0, 200, 255};
constexpr Rgb kZFightMark{255, 0, 0};

// The frame's targets and the auxiliary frames' (tightly packed rows), pixel by pixel.
class ViewPixels {
  public:
    explicit ViewPixels(const ViewInputs& in)
        : in_(in),
          s_(in.frame.debug_view),
          width_(in.frame.options->width),
          height_(in.frame.options->height) {}

    int width() const { return width_; }
    int height() const { return height_; }
    const Frame& frame() const { return in_.frame; }
    const Camera& camera() const { return in_.camera; }
    const DebugViewScratch& scratch() const { return s_; }
    std::size_t at(int px, int py) const { return std::size_t(py) * std::size_t(width_) + px; }

    std::int32_t instance(int px, int py) const { return s_.visible.instance_id[at(px, py)]; }
    std::int32_t primitive(int px, int py) const { return s_.visible.primitive_id[at(px, py)]; }
    bool visible(int px, int py) const { return instance(px, py) >= 0; }

    Rgb shaded(int px, int py) const {
        const std::uint8_t* p = color(px, py);
        return {p[0], p[1], p[2]};
    }
    void set(int px, int py, Rgb c) const {
        std::uint8_t* p = color(px, py);
        p[0] = c[0];
        p[1] = c[1];
        p[2] = c[2];
        p[3] = 255;
    }
    Rgb background() const {
        const glm::vec3 b = in_.frame.options->background;
        return {to_unorm8(b.x), to_unorm8(b.y), to_unorm8(b.z)};
    }
    // Every pixel through f(px, py) -> Rgb.
    template <class F>
    void paint(const F& f) const {
        for (int py = 0; py < height_; ++py)
            for (int px = 0; px < width_; ++px) set(px, py, f(px, py));
    }

  private:
    std::uint8_t* color(int px, int py) const {
        return target_row(in_.targets.color, in_.targets.color_pitch, py) + std::size_t(px) * 4;
    }
    const ViewInputs& in_;
    const DebugViewScratch& s_;
    int width_, height_;
};

// Counts 1..largest on the color scale, logarithmically (overdraw spans 1 to hundreds).
Rgb count_color(std::uint64_t count, std::uint64_t largest) {
    const double t = largest > 1 ? std::log(double(count)) / std::log(double(largest)) : 1.0;
    return debug_view_scale_color(t);
}

// The shaded image in dark grey: the context the marking views draw over.
Rgb dimmed(Rgb c) {
    const int luma = (77 * c[0] + 150 * c[1] + 29 * c[2]) >> 8;
    const auto v = static_cast<std::uint8_t>(16 + luma / 4);
    return {v, v, v};
}

// A quarter of the shaded color, three quarters of the tint: visible on any surface.
Rgb tinted(Rgb c, Rgb tint) {
    Rgb out{};
    for (std::size_t k = 0; k < 3; ++k) out[k] = std::uint8_t((c[k] + 3 * tint[k]) / 4);
    return out;
}

// splitmix64's finalizer: neighbouring ids get unrelated colors.
Rgb id_color(std::int32_t instance, std::int32_t primitive) {
    std::uint64_t z = (std::uint64_t(std::uint32_t(instance)) << 32) | std::uint32_t(primitive);
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    // Not too dark, so that every id stands out from a black or grey background.
    return {std::uint8_t(48 + (z & 0xff) % 208), std::uint8_t(48 + ((z >> 8) & 0xff) % 208),
            std::uint8_t(48 + ((z >> 16) & 0xff) % 208)};
}

DebugViewScale paint_depth(const ViewPixels& v) {
    const std::vector<float>& depth = v.scratch().visible.depth;
    // Eye distance where the projection has one; the window depth itself otherwise.
    bool metric = true;
    try {
        (void)linear_depth(v.camera(), 0.5);
    } catch (const InputError&) {
        metric = false;
    }
    const auto distance = [&](int px, int py) {
        const double z = depth[v.at(px, py)];
        return metric ? linear_depth(v.camera(), z) : z;
    };
    DebugViewScale scale{std::numeric_limits<double>::infinity(), 0.0};
    for (int py = 0; py < v.height(); ++py)
        for (int px = 0; px < v.width(); ++px)
            if (v.visible(px, py)) {
                const double d = distance(px, py);
                if (!std::isfinite(d)) continue;
                scale.low = std::min(scale.low, d);
                scale.high = std::max(scale.high, d);
            }
    if (!(scale.low <= scale.high)) scale = {};
    const double span = scale.high - scale.low;
    v.paint([&](int px, int py) {
        if (!v.visible(px, py)) return v.background();
        const double d = distance(px, py);
        return debug_view_scale_color(span > 0.0 ? 1.0 - (d - scale.low) / span : 1.0);
    });
    return scale;
}

DebugViewScale paint_normals(const ViewPixels& v) {
    const std::vector<glm::vec3>& normal = v.scratch().visible.normal;
    v.paint([&](int px, int py) {
        if (!v.visible(px, py)) return v.background();
        const glm::vec3 c = normal[v.at(px, py)] * 0.5f + 0.5f;
        return Rgb{to_unorm8(c.x), to_unorm8(c.y), to_unorm8(c.z)};
    });
    return {};
}

DebugViewScale paint_overdraw(const ViewPixels& v) {
    const RenderTargets& counts = v.scratch().overdraw;
    const auto fragments = [&](int px, int py) {
        const std::size_t at = v.at(px, py);
        return std::uint64_t(counts.front_hits[at]) + counts.back_hits[at];
    };
    std::uint64_t largest = 0;
    for (int py = 0; py < v.height(); ++py)
        for (int px = 0; px < v.width(); ++px) largest = std::max(largest, fragments(px, py));
    v.paint([&](int px, int py) {
        const std::uint64_t n = fragments(px, py);
        return n == 0 ? kBlack : count_color(n, largest);
    });
    return {largest > 0 ? 1.0 : 0.0, double(largest)};
}

DebugViewScale paint_hiz(const ViewPixels& v) {
    const std::vector<std::uint32_t>& blocks = v.scratch().hiz_blocks;
    const std::size_t blocks_per_row = std::size_t(v.frame().tiles_x) * kBlocksPerTileRow;
    const auto skipped = [&](int px, int py) {
        return blocks[std::size_t(py / kBlockSize) * blocks_per_row + std::size_t(px / kBlockSize)];
    };
    const std::uint32_t largest =
        blocks.empty() ? 0 : *std::max_element(blocks.begin(), blocks.end());
    v.paint([&](int px, int py) {
        const std::uint32_t n = skipped(px, py);
        return n == 0 ? dimmed(v.shaded(px, py)) : count_color(n, largest);
    });
    return {largest > 0 ? 1.0 : 0.0, double(largest)};
}

DebugViewScale paint_tiles(const ViewPixels& v) {
    const std::vector<std::size_t>& bins = v.frame().tile_bin_counts;
    const std::size_t tiles_x = std::size_t(v.frame().tiles_x);
    const auto binned = [&](int px, int py) {
        return bins[std::size_t(py / kTileSize) * tiles_x + std::size_t(px / kTileSize)];
    };
    const std::size_t largest = bins.empty() ? 0 : *std::max_element(bins.begin(), bins.end());
    v.paint([&](int px, int py) {
        const std::size_t n = binned(px, py);
        return n == 0 ? kBlack : count_color(n, largest);
    });
    return {largest > 0 ? 1.0 : 0.0, double(largest)};
}

DebugViewScale paint_ids(const ViewPixels& v) {
    v.paint([&](int px, int py) {
        return v.visible(px, py) ? id_color(v.instance(px, py), v.primitive(px, py))
                                 : v.background();
    });
    return {};
}

// The shaded image with the pixels whose triangle has `flag` tinted.
DebugViewScale paint_triangle_flag(const ViewPixels& v, std::uint8_t flag, Rgb tint) {
    v.paint([&](int px, int py) {
        const std::uint8_t flags =
            triangle_flags_of(v.frame(), v.instance(px, py), v.primitive(px, py));
        return (flags & flag) != 0 ? tinted(v.shaded(px, py), tint) : v.shaded(px, py);
    });
    return {};
}

DebugViewScale paint_zfight(const ViewPixels& v, bool has_reference) {
    const RenderTargets& visible = v.scratch().visible;
    const RenderTargets& reference = v.scratch().reference;
    std::uint64_t marked = 0;
    v.paint([&](int px, int py) {
        const std::size_t at = v.at(px, py);
        const bool differs =
            has_reference && (visible.instance_id[at] != reference.instance_id[at] ||
                              visible.primitive_id[at] != reference.primitive_id[at]);
        marked += differs;
        return differs ? kZFightMark : dimmed(v.shaded(px, py));
    });
    return {0.0, double(marked)};
}

// The coarsest level any instance's base-color texture has: the scale's top, the same for every
// view of the scene.
int coarsest_level(const Frame& frame) {
    int coarsest = 0;
    for (const FrameInstance& fi : frame.instances)
        if (fi.textured && fi.material->base_color_texture)
            coarsest = std::max(coarsest, fi.material->base_color_texture->levels() - 1);
    return coarsest;
}

DebugViewScale paint_mip(const ViewPixels& v) {
    const int coarsest = coarsest_level(v.frame());
    v.paint([&](int px, int py) {
        const FrameInstance* fi = frame_instance_of(v.frame(), v.instance(px, py));
        if (fi == nullptr) return v.background();
        const std::optional<float> level =
            sampled_mip_level(v.frame(), *fi, std::uint32_t(v.primitive(px, py)), px, py);
        if (!level) return kUntextured;
        return debug_view_scale_color(coarsest > 0 ? *level / float(coarsest) : 0.0);
    });
    return {0.0, double(coarsest)};
}

}  // namespace

DebugViewScale paint_debug_view(DebugView view, const ViewInputs& in) {
    const ViewPixels v(in);
    switch (view) {
        case DebugView::None:
            return {};
        case DebugView::Depth:
            return paint_depth(v);
        case DebugView::Normals:
            return paint_normals(v);
        case DebugView::Overdraw:
            return paint_overdraw(v);
        case DebugView::HiZ:
            return paint_hiz(v);
        case DebugView::Tiles:
            return paint_tiles(v);
        case DebugView::Ids:
            return paint_ids(v);
        case DebugView::Backfaces:
            return paint_triangle_flag(v, kTriangleBack, kBackTint);
        case DebugView::Clipped:
            return paint_triangle_flag(v, kTriangleClipped, kClippedTint);
        case DebugView::ZFight:
            return paint_zfight(v, in.frame.options->depth_format != DepthFormat::D32F);
        case DebugView::Mip:
            return paint_mip(v);
    }
    return {};
}

}  // namespace zraster::detail
