// Depth buffers in three formats and the eight OpenGL compare functions.
//
// D32F stores the window depth as a float; D24 and D16 store round(depth * (2^n - 1)) as
// unsigned normalized integers, as OpenGL converts depth to fixed point. Fragments are quantized
// to the buffer's format before the comparison, so a D16 buffer shows exactly the z-fighting a
// 16-bit hardware buffer would.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>
#include <zraster/export.hpp>

namespace zraster {

enum class DepthFormat { D32F, D24, D16 };
enum class CompareFunc { Never, Less, LessEqual, Equal, NotEqual, GreaterEqual, Greater, Always };

class ZRASTER_API DepthBuffer {
  public:
    DepthBuffer() = default;
    DepthBuffer(int width, int height, DepthFormat format);

    int width() const { return width_; }
    int height() const { return height_; }
    DepthFormat format() const { return format_; }

    void clear(float depth);
    // The stored value of a window depth in [0, 1] (float bits for D32F, unorm for D24/D16).
    std::uint32_t encode(float depth) const;
    float decode(std::uint32_t stored) const;
    float read(int x, int y) const { return decode(values_[index(x, y)]); }

    // Depth test of one fragment; writes the fragment's depth when it passes and write is set.
    bool test_and_write(int x, int y, float depth, CompareFunc compare, bool write) {
        const std::uint32_t incoming = encode(depth);
        std::uint32_t& stored = values_[index(x, y)];
        const bool pass = format_ == DepthFormat::D32F
                              ? passes(bits_to_float(incoming), bits_to_float(stored), compare)
                              : passes(incoming, stored, compare);
        if (pass && write) stored = incoming;
        return pass;
    }

    template <class T>
    static bool passes(T incoming, T stored, CompareFunc compare) {
        switch (compare) {
            case CompareFunc::Never:
                return false;
            case CompareFunc::Less:
                return incoming < stored;
            case CompareFunc::LessEqual:
                return incoming <= stored;
            case CompareFunc::Equal:
                return incoming == stored;
            case CompareFunc::NotEqual:
                return incoming != stored;
            case CompareFunc::GreaterEqual:
                return incoming >= stored;
            case CompareFunc::Greater:
                return incoming > stored;
            case CompareFunc::Always:
                return true;
        }
        return false;
    }

  private:
    static float bits_to_float(std::uint32_t bits);
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_ = 0, height_ = 0;
    DepthFormat format_ = DepthFormat::D32F;
    std::vector<std::uint32_t> values_;
};

// Parsing helpers for the command line and scene files ("d32f", "d24", "d16"; "less", ...).
ZRASTER_API bool parse_depth_format(std::string_view text, DepthFormat& out);
ZRASTER_API bool parse_compare_func(std::string_view text, CompareFunc& out);

}  // namespace zraster
