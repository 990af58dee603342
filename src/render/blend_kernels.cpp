// See blend_kernels.hpp. Highway's foreach_target re-includes this file once per instruction
// set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/blend_kernels.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "raster/tile_layout.hpp"
#include "render/blend_kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void AppendBlendRow(const BlendRow& row, TileBuffers& buffers, const float* opaque_depth,
                    BlendSlots& slots) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto id = hn::Set(du, row.id);
    const auto no_triangle = hn::Set(du, kNoTriangle);
    const auto last_slot = hn::Set(du, kBlendSlots - 1);
    const auto flip = hn::Set(du, row.greater_is_nearer ? 0u : ~0u);  // blend_depth_key
    const auto alpha = hn::Set(d, row.alpha);
    const auto source = hn::Set(du, row.source);
    alignas(64) std::uint32_t counts[hn::MaxLanes(du)];
    int i = 0;
    for (; i + lanes <= row.width; i += lanes) {
        const std::size_t at = row.at + std::size_t(i);
        const std::size_t pixel = row.pixel + std::size_t(i);
        const auto mine = hn::Eq(hn::LoadU(du, buffers.ref + at), id);
        if (hn::AllFalse(du, mine)) continue;
        const auto n = hn::LoadU(du, slots.count.data() + pixel);
        const auto full = hn::And(mine, hn::Gt(n, last_slot));
        const auto take = hn::AndNot(full, mine);
        if (!hn::AllFalse(du, take)) {
            const auto key = hn::Xor(hn::BitCast(du, hn::LoadU(d, buffers.depth + at)), flip);
            const auto rgba = hn::LoadU(du, buffers.color + at);
            // (Blends and whole stores, not masked stores: those are slow on AMD's AVX2. Every
            // lane here is the row's and this thread's.)
            const auto blend_u = [&](auto m, auto v, std::uint32_t* to) {
                hn::StoreU(hn::IfThenElse(m, v, hn::LoadU(du, to)), du, to);
            };
            const auto blend_f = [&](auto m, auto v, float* to) {
                hn::StoreU(hn::IfThenElse(hn::RebindMask(d, m), v, hn::LoadU(d, to)), d, to);
            };
            blend_u(take, no_triangle, buffers.ref + at);
            blend_f(take, hn::LoadU(d, opaque_depth + at), buffers.depth + at);
            hn::StoreU(hn::IfThenElse(take, hn::Add(n, hn::Set(du, 1u)), n), du,
                       slots.count.data() + pixel);
            // Each slot layer the lanes append to (all one, mostly).
            hn::Store(n, du, counts);
            auto pending = take;
            do {
                const std::uint32_t layer = counts[hn::FindFirstTrue(du, pending)];
                const auto these = hn::And(pending, hn::Eq(n, hn::Set(du, layer)));
                const std::size_t slot = layer * slots.pixels + pixel;
                blend_u(these, key, slots.depth_key.data() + slot);
                blend_u(these, rgba, slots.rgba.data() + slot);
                blend_u(these, source, slots.source.data() + slot);
                blend_f(these, alpha, slots.alpha.data() + slot);
                pending = hn::AndNot(these, pending);
            } while (!hn::AllFalse(du, pending));
        }
        if (!hn::AllFalse(du, full))  // (their fragments go to BlendSlots::more)
            for (int lane = 0; lane < lanes; ++lane)
                append_blend_pixel(row, i + lane, buffers, opaque_depth, slots);
    }
    for (; i < row.width; ++i) append_blend_pixel(row, i, buffers, opaque_depth, slots);
}

void CompositeBlendRow(const BlendSlots& slots, std::size_t pixel, int width,
                       const CompositingOrder& order, std::uint8_t* color) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto byte = hn::Set(du, 0xffu);
    const auto from_unorm8 = hn::Set(d, 1.0f / 255.0f);
    const auto one = hn::Set(d, 1.0f), to_unorm8 = hn::Set(d, 255.0f), half = hn::Set(d, 0.5f);
    const auto slot_count = hn::Set(du, kBlendSlots);
    const auto farthest = hn::Set(du, ~0u);
    const auto channel = [&](auto v, int shift) {
        return hn::Mul(
            hn::ConvertTo(d, hn::BitCast(di, hn::And(hn::ShiftRightSame(v, shift), byte))),
            from_unorm8);
    };
    const auto unorm8 = [&](auto c) {
        return hn::BitCast(du, hn::ConvertTo(di, hn::Add(hn::Mul(c, to_unorm8), half)));
    };
    int i = 0;
    for (; i + lanes <= width; i += lanes) {
        const std::size_t p = pixel + std::size_t(i);
        const auto n = hn::LoadU(du, slots.count.data() + p);
        const auto drawn = hn::AndNot(hn::Gt(n, slot_count), hn::Gt(n, hn::Zero(du)));
        if (hn::AllFalse(du, drawn)) continue;
        auto* pixels = reinterpret_cast<std::uint32_t*>(color) + i;
        const auto dst = hn::LoadU(du, pixels);
        auto r = channel(dst, 0), g = channel(dst, 8), b = channel(dst, 16);
        const auto over = [&](auto rgba, auto a) {  // one layer; alpha 0 leaves c exactly
            const auto keep = hn::Sub(one, a);
            r = hn::Add(hn::Mul(channel(rgba, 0), a), hn::Mul(r, keep));
            g = hn::Add(hn::Mul(channel(rgba, 8), a), hn::Mul(g, keep));
            b = hn::Add(hn::Mul(channel(rgba, 16), a), hn::Mul(b, keep));
        };
        const std::uint32_t most = hn::GetLane(hn::MaxOfLanes(du, hn::IfThenElseZero(drawn, n)));
        if (most == 1) {
            over(
                hn::LoadU(du, slots.rgba.data() + p),
                hn::IfThenElseZero(hn::RebindMask(d, drawn), hn::LoadU(d, slots.alpha.data() + p)));
        } else {
            // The layers, those a lane does not have as the farthest with alpha 0 (they then
            // change nothing wherever the sort puts them).
            hn::Vec<decltype(du)> key[kBlendSlots], rgba[kBlendSlots];
            hn::Vec<decltype(d)> alpha[kBlendSlots];
            hn::Mask<decltype(du)> valid[kBlendSlots];
            for (std::uint32_t l = 0; l < kBlendSlots; ++l) {
                const std::size_t at = l * slots.pixels + p;
                valid[l] = hn::And(drawn, hn::Lt(hn::Set(du, l), n));
                key[l] =
                    hn::IfThenElse(valid[l], hn::LoadU(du, slots.depth_key.data() + at), farthest);
                rgba[l] = hn::LoadU(du, slots.rgba.data() + at);
                alpha[l] = hn::IfThenElseZero(hn::RebindMask(d, valid[l]),
                                              hn::LoadU(d, slots.alpha.data() + at));
            }
            // Equal depths are ordered by content and ids: the scalar way, pixel by pixel.
            auto ties = hn::FirstN(du, 0);
            for (std::uint32_t a = 0; a < kBlendSlots; ++a)
                for (std::uint32_t z = a + 1; z < kBlendSlots; ++z)
                    ties = hn::Or(ties, hn::And(valid[z], hn::Eq(key[a], key[z])));
            if (!hn::AllFalse(du, ties)) {
                for (int lane = 0; lane < lanes; ++lane) {
                    const std::uint32_t count = slots.count[p + std::size_t(lane)];
                    if (count != 0 && count <= kBlendSlots)
                        composite_slots_pixel(slots, p + std::size_t(lane), order,
                                              color + std::size_t(i + lane) * 4);
                }
                continue;
            }
            // A sorting network on the keys (distinct among a lane's valid layers).
            const auto exchange = [&](std::uint32_t x, std::uint32_t y) {
                const auto swap = hn::Lt(key[y], key[x]);
                const auto k = key[x];
                key[x] = hn::IfThenElse(swap, key[y], k);
                key[y] = hn::IfThenElse(swap, k, key[y]);
                const auto c = rgba[x];
                rgba[x] = hn::IfThenElse(swap, rgba[y], c);
                rgba[y] = hn::IfThenElse(swap, c, rgba[y]);
                const auto swap_f = hn::RebindMask(d, swap);
                const auto a = alpha[x];
                alpha[x] = hn::IfThenElse(swap_f, alpha[y], a);
                alpha[y] = hn::IfThenElse(swap_f, a, alpha[y]);
            };
            static_assert(kBlendSlots == 4, "the network sorts four");
            exchange(0, 1);
            exchange(2, 3);
            exchange(0, 2);
            exchange(1, 3);
            exchange(1, 2);
            for (std::uint32_t l = 0; l < kBlendSlots; ++l) over(rgba[l], alpha[l]);
        }
        const auto packed =
            hn::Or(hn::Or(unorm8(r), hn::ShiftLeft<8>(unorm8(g))),
                   hn::Or(hn::ShiftLeft<16>(unorm8(b)), hn::And(dst, hn::Set(du, 0xff000000u))));
        hn::StoreU(hn::IfThenElse(drawn, packed, dst), du, pixels);
    }
    for (; i < width; ++i) {
        const std::uint32_t count = slots.count[pixel + std::size_t(i)];
        if (count != 0 && count <= kBlendSlots)
            composite_slots_pixel(slots, pixel + std::size_t(i), order, color + std::size_t(i) * 4);
    }
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(AppendBlendRow);
HWY_EXPORT(CompositeBlendRow);

void append_blend_row(const BlendRow& row, TileBuffers& buffers, const float* opaque_depth,
                      BlendSlots& slots) {
    HWY_DYNAMIC_DISPATCH(AppendBlendRow)(row, buffers, opaque_depth, slots);
}

void append_blend_row_scalar(const BlendRow& row, TileBuffers& buffers, const float* opaque_depth,
                             BlendSlots& slots) {
    for (int i = 0; i < row.width; ++i) append_blend_pixel(row, i, buffers, opaque_depth, slots);
}

void composite_blend_row(const BlendSlots& slots, std::size_t pixel, int width,
                         const CompositingOrder& order, std::uint8_t* color) {
    HWY_DYNAMIC_DISPATCH(CompositeBlendRow)(slots, pixel, width, order, color);
}

void composite_blend_row_scalar(const BlendSlots& slots, std::size_t pixel, int width,
                                const CompositingOrder& order, std::uint8_t* color) {
    for (int i = 0; i < width; ++i) {
        const std::uint32_t count = slots.count[pixel + std::size_t(i)];
        if (count != 0 && count <= kBlendSlots)
            composite_slots_pixel(slots, pixel + std::size_t(i), order, color + std::size_t(i) * 4);
    }
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
