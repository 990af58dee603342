// See shade_kernel.hpp. Highway's foreach_target re-includes this file once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shade_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "render/shade_kernel.hpp"

// Per target, like this file.
#include "shade/phong_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The tagged pixels of the N vectors of a row at the offsets `starts` (all of one material,
// constants `k`), written over rgba.
template <int N, class D>
HWY_INLINE void shade_row_group(D d, const PhongConstants& k, const TileBuffers& tile,
                                std::size_t at, int count, const int* starts, std::uint32_t* rgba) {
    const hn::RebindToUnsigned<D> du;
    const auto flip_bit = hn::Set(du, kShadeFlip);
    const auto from = [&](const float* v) {
        return group_of<N>([&](int j) { return hn::LoadU(d, v + at + std::size_t(starts[j])); });
    };
    const auto flip = group_of<N>([&](int j) {
        const auto tag = hn::LoadU(du, tile.shade_tag + at + std::size_t(starts[j]));
        return hn::RebindMask(d, hn::Ne(hn::And(tag, flip_bit), hn::Zero(du)));
    });
    const auto color =
        pack_rgba(du, shade_lanes(d, k, from(tile.nx), from(tile.ny), from(tile.nz), from(tile.wx),
                                  from(tile.wy), from(tile.wz), flip));
    for_each_of<N>(color, [&](const auto& c, int j) {
        const auto start = static_cast<std::size_t>(starts[j]);
        const auto tag = hn::LoadU(du, tile.shade_tag + at + start);
        const auto pending = hn::And(hn::Ne(hn::AndNot(flip_bit, tag), hn::Zero(du)),
                                     hn::FirstN(du, std::size_t(count) - start));
        hn::StoreU(hn::IfThenElse(pending, c, hn::LoadU(du, rgba + start)), du, rgba + start);
    });
}

int ShadeTaggedRow(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                   int count, std::uint32_t* rgba) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto flip_bit = hn::Set(du, kShadeFlip);
    int shaded = 0;
    // Vectors whose tagged pixels are all of material queued_tag wait here to be shaded
    // kShadeGroup at a time.
    int queued[kShadeGroup], queued_count = 0;
    std::uint32_t queued_tag = 0;
    const auto flush = [&] {
        const PhongConstants& k = constants[queued_tag - 1];
        if (queued_count == 1) shade_row_group<1>(d, k, tile, at, count, queued, rgba);
        if (queued_count == 2) shade_row_group<2>(d, k, tile, at, count, queued, rgba);
        if (queued_count >= 3) {
            // Three as four (the third twice): as fast as two and one.
            queued[3] = queued[queued_count - 1];
            shade_row_group<4>(d, k, tile, at, count, queued, rgba);
        }
        queued_count = 0;
    };
    for (int i = 0; i < count; i += lanes) {
        const std::size_t p = at + std::size_t(i);
        const auto tag = hn::LoadU(du, tile.shade_tag + p);
        const auto kernel = hn::AndNot(flip_bit, tag);
        auto pending = hn::And(hn::Ne(kernel, hn::Zero(du)),
                               hn::FirstN(du, static_cast<std::size_t>(count - i)));
        if (hn::AllFalse(du, pending)) continue;
        shaded += static_cast<int>(hn::CountTrue(du, pending));
        const auto first = static_cast<std::size_t>(hn::FindFirstTrue(du, pending));
        // (From memory: a lane extracted at a run-time index goes through the stack.)
        const std::uint32_t which = tile.shade_tag[p + first] & ~kShadeFlip;
        const auto mine = hn::And(pending, hn::Eq(kernel, hn::Set(du, which)));
        if (hn::AllFalse(du, hn::AndNot(mine, pending))) {  // one material: queue the vector
            if (queued_count > 0 && queued_tag != which) flush();
            queued_tag = which;
            queued[queued_count++] = i;
            if (queued_count == kShadeGroup) flush();
            continue;
        }
        // Several materials: one pass per material present.
        const auto nx = hn::LoadU(d, tile.nx + p), ny = hn::LoadU(d, tile.ny + p),
                   nz = hn::LoadU(d, tile.nz + p);
        const auto px = hn::LoadU(d, tile.wx + p), py = hn::LoadU(d, tile.wy + p),
                   pz = hn::LoadU(d, tile.wz + p);
        const auto flip = hn::RebindMask(d, hn::Ne(hn::And(tag, flip_bit), hn::Zero(du)));
        auto out = hn::LoadU(du, rgba + i);
        do {
            const auto lane = static_cast<std::size_t>(hn::FindFirstTrue(du, pending));
            const std::uint32_t material = tile.shade_tag[p + lane] & ~kShadeFlip;
            const auto these = hn::And(pending, hn::Eq(kernel, hn::Set(du, material)));
            const auto color = pack_rgba(
                du, shade_lanes(d, constants[material - 1], nx, ny, nz, px, py, pz, flip));
            out = hn::IfThenElse(these, color, out);
            pending = hn::AndNot(these, pending);
        } while (!hn::AllFalse(du, pending));
        hn::StoreU(out, du, rgba + i);
    }
    if (queued_count > 0) flush();
    return shaded;
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(ShadeTaggedRow);

int shade_tagged_row(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                     int count, std::uint32_t* rgba) {
    return HWY_DYNAMIC_DISPATCH(ShadeTaggedRow)(constants, tile, at, count, rgba);
}

int shade_tagged_row_scalar(const PhongConstants* constants, const TileBuffers& tile,
                            std::size_t at, int count, std::uint32_t* rgba) {
    PhongBatch one;
    one.count = 1;
    int shaded = 0;
    for (int i = 0; i < count; ++i) {
        const std::size_t p = at + std::size_t(i);
        const std::uint32_t kernel = tile.shade_tag[p] & ~kShadeFlip;
        if (kernel == 0) continue;
        ++shaded;
        one.nx[0] = tile.nx[p];
        one.ny[0] = tile.ny[p];
        one.nz[0] = tile.nz[p];
        one.px[0] = tile.wx[p];
        one.py[0] = tile.wy[p];
        one.pz[0] = tile.wz[p];
        one.flip[0] = (tile.shade_tag[p] & kShadeFlip) ? ~0u : 0u;
        shade_phong_batch_scalar(constants[kernel - 1], one);
        rgba[i] = batch_rgba(one, 0);
    }
    return shaded;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
