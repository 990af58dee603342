// See blend_pass.hpp.
#include "render/blend_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <utility>

#include "raster/tile_layout.hpp"
#include "render/blend_kernels.hpp"
#include "render/shade_fragment.hpp"
#include "render/tile_traversal.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

float unit_clamp(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0)
}

std::uint32_t pack_rgba8(const glm::vec3& c) {
    return std::uint32_t(to_unorm8(c.x)) | std::uint32_t(to_unorm8(c.y)) << 8 |
           std::uint32_t(to_unorm8(c.z)) << 16 | 0xff000000u;
}

// Where a tile's fragments go: their pixels' slots.
struct FragmentSink {
    BlendSlots& slots;
    bool greater_is_nearer;
    void add(std::uint32_t pixel, const BlendFragment& f) { slots.add(pixel, f); }
};

// The colors of a triangle's fragments lit by the SIMD Phong shader (the scalar twin without
// SIMD), a batch at a time: the values the deferred pass gives an opaque pixel of it.
class PhongFragments {
  public:
    PhongFragments(const PhongConstants& constants, const CornerAttributes& corners,
                   const glm::vec3* piece, bool simd, std::vector<PendingFragment>& pending)
        : constants_(constants), corners_(corners), piece_(piece), simd_(simd), pending_(pending) {
        batch_.count = 0;
    }
    // Pending fragment `index`, at barycentrics (b1, b2) of the piece.
    void add(std::size_t index, float b1, float b2) {
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
        index_[i] = std::uint32_t(index);
        if (batch_.count == kShadeBatch) flush();
    }
    void flush() {
        if (batch_.count == 0) return;
        if (simd_)
            shade_phong_batch(constants_, batch_);
        else
            shade_phong_batch_scalar(constants_, batch_);
        for (int i = 0; i < batch_.count; ++i)
            pending_[index_[i]].fragment.rgba = batch_rgba(batch_, i);
        batch_.count = 0;
    }

  private:
    const PhongConstants& constants_;
    const CornerAttributes& corners_;
    const glm::vec3* piece_;
    bool simd_;
    std::vector<PendingFragment>& pending_;
    PhongBatch batch_;
    std::uint32_t index_[kShadeBatch];
};

// The alpha of a material without alpha textures is its opacity everywhere; -1 when it varies.
float constant_fragment_alpha(const Frame& frame, const FrameInstance& fi,
                              const ShadingTriangle& shading) {
    return fi.alpha_varies.any() ? -1.0f : unit_clamp(fragment_alpha(frame, shading, 0, 0, 0, 0));
}

// What the fragment generators know of a blended triangle.
struct BlendSource {
    const Chunk& chunk;
    const TriangleRef& ref;
    const FrameInstance& instance;
    ShadingTriangle shading;
    CornerAttributes corners;
    const glm::vec3* piece;  // a clipped piece's corner weights, or null
    float constant_alpha;    // -1: alpha textures or vertex alpha, computed per fragment

    BlendSource(const Frame& frame, const BlendTriangle& blended)
        : chunk(frame.chunks[blended.chunk]),
          ref(chunk.refs[blended.ref]),
          instance(frame.instances[ref.instance]),
          piece(ref.piece == TriangleRef::kNotClipped ? nullptr
                                                      : chunk.pieces[ref.piece].weights.data()) {
        prepare_shading_triangle(frame, chunk, ref, shading);
        corner_attributes(frame, ref, corners);
        constant_alpha = constant_fragment_alpha(frame, instance, shading);
    }
    float alpha(const Frame& frame, float b1, float b2, int px, int py) const {
        return constant_alpha >= 0.0f ? constant_alpha
                                      : unit_clamp(fragment_alpha(frame, shading, b1, b2, px, py));
    }
};

// A triangle's fragments whose colors are computed here rather than by the kernel: queued
// with their barycentrics, shaded (Phong in batches, other modes one by one), then sunk.
class ShadedHere {
  public:
    ShadedHere(const Frame& frame, const BlendSource& s, std::vector<PendingFragment>& pending)
        : frame_(frame), s_(s), pending_(pending) {
        pending_.clear();
        if (s.corners.tag != 0)
            phong_.emplace(frame.phong_constants[std::size_t(s.instance.phong_kernel)], s.corners,
                           s.piece, frame.options->simd, pending);
    }
    void add(std::uint32_t pixel, const BlendFragment& f, float b1, float b2, int px, int py) {
        pending_.push_back({pixel, f});
        if (phong_)
            phong_->add(pending_.size() - 1, b1, b2);
        else
            pending_.back().fragment.rgba =
                pack_rgba8(shade_fragment(frame_, s_.shading, b1, b2, px, py, false).color);
    }
    void finish(FragmentSink& sink) {
        if (phong_) phong_->flush();
        for (const PendingFragment& p : pending_) sink.add(p.pixel, p.fragment);
    }

  private:
    const Frame& frame_;
    const BlendSource& s_;
    std::vector<PendingFragment>& pending_;
    std::optional<PhongFragments> phong_;
};

// The fragments of the blended triangles in front of the opaque depths, by the visibility
// kernel: each triangle is drawn into `buffers` (the opaque depths, no triangle), whose
// pixels it passed are then read out and restored. Phong instances without alpha textures are
// lit by the kernel as they pass (forward); the others get their barycentrics and are shaded
// here.
void kernel_fragments(const TileContext& c, const TileBuffers& tile, TileBuffers& buffers,
                      BlendScratch& scratch, FragmentSink& sink) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const RenderOptions& options = *frame.options;
    const int width = c.x1 - c.x0;
    for (int y = 0; y < c.y1 - c.y0; ++y) {
        std::memcpy(buffers.depth + tile_index(0, y), tile.depth + tile_index(0, y),
                    std::size_t(width) * sizeof(float));
        std::memset(buffers.ref + tile_index(0, y), 0xff,
                    std::size_t(width) * sizeof(std::uint32_t));  // kNoTriangle
    }
    BlockJob job;
    job.perspective = options.interpolation == Interpolation::PerspectiveCorrect;
    job.compare = plan.compare;
    job.write_depth = true;  // into `buffers`: the fragment's depth, read out below
    job.attributes = true;
    job.barycentrics = true;
    for (std::uint32_t source = 0; source < scratch.triangles.size(); ++source) {
        const BlendTriangle& blended = scratch.triangles[source];
        const BlendSource s(frame, blended);
        if (s.constant_alpha == 0.0f) continue;
        const bool forward = s.corners.tag != 0 && s.constant_alpha > 0.0f;
        const TriangleSetup& setup = blended.setup;
        const std::uint32_t id = triangle_reference(blended.chunk, blended.ref);
        draw_into_side(
            c,
            TileTriangle{
                s.chunk, s.ref, setup, id, forward ? &s.corners : nullptr, s.piece,
                forward ? &frame.phong_constants[(s.corners.tag & ~kShadeFlip) - 1] : nullptr},
            job, buffers);

        // Read out (and restore) the pixels it passed, row by row.
        const int rx0 = std::max(setup.min_x, c.x0), ry0 = std::max(setup.min_y, c.y0);
        const int rx1 = std::min(setup.max_x, c.x1 - 1), ry1 = std::min(setup.max_y, c.y1 - 1);
        if (forward) {  // lit by the kernel, one alpha: a kernel of their own
            const auto append = plan.simd ? append_blend_row : append_blend_row_scalar;
            for (int py = ry0; py <= ry1; ++py)
                append(BlendRow{tile_index(rx0 - c.x0, py - c.y0),
                                std::size_t((py - c.y0) * width + (rx0 - c.x0)), rx1 - rx0 + 1, id,
                                s.constant_alpha, source, sink.greater_is_nearer},
                       buffers, tile.depth, sink.slots);
            continue;
        }
        std::optional<ShadedHere> here;
        here.emplace(frame, s, scratch.pending);
        for (int py = ry0; py <= ry1; ++py) {
            const std::size_t row = tile_index(0, py - c.y0) - std::size_t(c.x0);
            const int pixel_row = (py - c.y0) * width - c.x0;
            for (int px = rx0; px <= rx1; ++px) {
                const std::size_t at = row + std::size_t(px);
                if (buffers.ref[at] != id) continue;
                buffers.ref[at] = kNoTriangle;
                const std::uint32_t key =
                    blend_depth_key(buffers.depth[at], sink.greater_is_nearer);
                buffers.depth[at] = tile.depth[at];
                const float b1 = buffers.b1[at], b2 = buffers.b2[at];
                const float alpha = s.alpha(frame, b1, b2, px, py);
                if (alpha != 0.0f)
                    here->add(std::uint32_t(pixel_row + px), {key, alpha, 0, source}, b1, b2, px,
                              py);
            }
        }
        if (here) here->finish(sink);
    }
}

// The same, pixel by pixel: any depth format, the depth test off (the scalar traversal's
// frames).
void scalar_fragments(const TileContext& c, const TileBuffers& tile, BlendScratch& scratch,
                      FragmentSink& sink) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const RenderOptions& options = *frame.options;
    const int width = c.x1 - c.x0;
    for (std::uint32_t source = 0; source < scratch.triangles.size(); ++source) {
        const BlendTriangle& blended = scratch.triangles[source];
        const BlendSource s(frame, blended);
        if (s.constant_alpha == 0.0f) continue;
        ShadedHere here(frame, s, scratch.pending);
        for_each_covered_pixel(blended.setup, c.x0, c.y0, c.x1, c.y1, [&](int px, int py) {
            const std::size_t at = tile_index(px - c.x0, py - c.y0);
            const float z = depth_at(blended.setup, px, py);
            const float code = plan.codec.format() == DepthFormat::D32F
                                   ? z
                                   : static_cast<float>(plan.codec.encode(z));
            if (options.depth_test && !DepthBuffer::passes(code, tile.depth[at], plan.compare))
                return;
            const glm::vec3 b = barycentrics(blended.setup, px, py, options.interpolation);
            const float alpha = s.alpha(frame, b.y, b.z, px, py);
            if (alpha == 0.0f) return;
            here.add(std::uint32_t((py - c.y0) * width + (px - c.x0)),
                     {blend_depth_key(code, sink.greater_is_nearer), alpha, 0, source}, b.y, b.z,
                     px, py);
        });
        here.finish(sink);
    }
}

}  // namespace

BlendCounts composite_blended(const TileContext& c, const TileBuffers& tile, TileBuffers& side,
                              BlendScratch& scratch) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const int width = c.x1 - c.x0;
    const std::size_t pixels = std::size_t(width) * std::size_t(c.y1 - c.y0);
    std::vector<std::uint32_t>& instance = scratch.instance;
    std::vector<std::uint32_t>& primitive = scratch.primitive;
    instance.resize(scratch.triangles.size());
    primitive.resize(scratch.triangles.size());
    for (std::size_t t = 0; t < scratch.triangles.size(); ++t) {
        const TriangleRef& ref =
            frame.chunks[scratch.triangles[t].chunk].refs[scratch.triangles[t].ref];
        instance[t] = frame.instances[ref.instance].scene_instance;
        primitive[t] = ref.primitive;
    }
    BlendSlots& slots = scratch.slots;
    slots.start(pixels);
    FragmentSink sink{
        slots, plan.compare == CompareFunc::Greater || plan.compare == CompareFunc::GreaterEqual};
    if (plan.traversal == Traversal::Blocks && frame.options->depth_write)
        kernel_fragments(c, tile, side, scratch, sink);
    else
        scalar_fragments(c, tile, scratch, sink);
    BlendCounts counts;
    for (std::size_t p = 0; p < pixels; ++p) {
        counts.fragments += slots.count[p];
        counts.pixels += slots.count[p] != 0;
    }
    if (counts.fragments == 0) return counts;

    // Pixels with at most kBlendSlots fragments, a vector of them at a time; then the others.
    const CompositingOrder order{instance.data(), primitive.data()};
    const TargetViews& t = plan.targets.views;
    const auto composite = plan.simd ? composite_blend_row : composite_blend_row_scalar;
    for (int y = c.y0; y < c.y1; ++y)
        composite(slots, std::size_t(y - c.y0) * std::size_t(width), width, order,
                  target_row(t.color, t.color_pitch, y) + std::size_t(c.x0) * 4);
    if (!slots.more.empty()) {
        std::sort(slots.more.begin(), slots.more.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<BlendFragment>& list = scratch.list;
        for (std::size_t i = 0; i < slots.more.size();) {
            const std::uint32_t pixel = slots.more[i].first;
            list.clear();
            for (std::uint32_t k = 0; k < kBlendSlots; ++k) list.push_back(slots.slot(pixel, k));
            for (; i < slots.more.size() && slots.more[i].first == pixel; ++i)
                list.push_back(slots.more[i].second);
            std::sort(list.begin(), list.end(), order);
            const int px = c.x0 + int(pixel % std::uint32_t(width));
            const int py = c.y0 + int(pixel / std::uint32_t(width));
            composite_fragments(list.data(), list.size(),
                                target_row(t.color, t.color_pitch, py) + std::size_t(px) * 4);
        }
    }
    return counts;
}

}  // namespace zraster::detail
