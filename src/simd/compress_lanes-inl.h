// CompressLanes(d, v, mask): the lanes of v where mask is set, moved to the front in order (the
// other lanes unspecified), as hn::Compress does it, for 32-bit lanes.
//
// Why not hn::Compress: on x86 without AVX-512, Highway 1.0.3 (Debian 12's) looks the lane
// order up in a table that is a constexpr local array, not a static one, and GCC copies it to
// the stack on every call (1 KiB for 8 lanes): occluder setup ran 2.5x slower on AVX2 than it
// does with the static table here. AVX-512 has a compress instruction and other targets keep
// Highway's.
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_SIMD_COMPRESS_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_SIMD_COMPRESS_LANES_INL_H_
#undef ZRASTER_SIMD_COMPRESS_LANES_INL_H_
#else
#define ZRASTER_SIMD_COMPRESS_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <array>
#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_ARCH_X86 && HWY_TARGET > HWY_AVX3 && HWY_TARGET != HWY_SCALAR
// For each mask of kLanes bits, the source lane of each output lane, 4 bits per lane (lane i in
// bits 4i..4i+3): the selected lanes in order, then the others.
template <std::size_t kLanes>
constexpr std::array<std::uint32_t, std::size_t{1} << kLanes> compress_lane_order() {
    std::array<std::uint32_t, std::size_t{1} << kLanes> table{};
    for (std::size_t mask = 0; mask < table.size(); ++mask) {
        std::uint32_t packed = 0;
        std::size_t out = 0;
        for (int selected = 1; selected >= 0; --selected)
            for (std::size_t lane = 0; lane < kLanes; ++lane)
                if (((mask >> lane) & 1u) == std::size_t(selected))
                    packed |= std::uint32_t(lane) << (4 * out++);
        table[mask] = packed;
    }
    return table;
}
#endif

template <class D>
HWY_INLINE hn::Vec<D> CompressLanes(D d, hn::Vec<D> v, hn::Mask<D> mask) {
    static_assert(sizeof(hn::TFromD<D>) == 4, "32-bit lanes");
#if HWY_ARCH_X86 && HWY_TARGET > HWY_AVX3 && HWY_TARGET != HWY_SCALAR
    constexpr std::size_t kLanes = hn::MaxLanes(D());
    if constexpr (kLanes == 4 || kLanes == 8) {
        static constexpr auto kOrder = compress_lane_order<kLanes>();
        const hn::RebindToUnsigned<D> du;
        alignas(8) std::uint8_t bits[8] = {};
        hn::StoreMaskBits(d, mask, bits);
        const auto packed = hn::Set(du, kOrder[bits[0]]);
        const auto shifts = hn::ShiftLeft<2>(hn::Iota(du, 0));  // 4 bits per lane
        const auto order = hn::And(hn::Shr(packed, shifts), hn::Set(du, kLanes - 1));
        return hn::TableLookupLanes(v, hn::IndicesFromVec(d, order));
    }
#endif
    (void)d;
    return hn::Compress(v, mask);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
