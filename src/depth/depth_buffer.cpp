#include <zraster/depth_buffer.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace zraster {

DepthBuffer::DepthBuffer(int width, int height, DepthFormat format)
    : width_(width),
      height_(height),
      format_(format),
      values_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    clear(1.0f);
}

void DepthBuffer::clear(float depth) {
    std::fill(values_.begin(), values_.end(), encode(depth));
}

float DepthBuffer::bits_to_float(std::uint32_t bits) {
    return std::bit_cast<float>(bits);
}

std::uint32_t DepthBuffer::encode(float depth) const {
    const float d = std::clamp(depth, 0.0f, 1.0f);
    switch (format_) {
        case DepthFormat::D32F:
            return std::bit_cast<std::uint32_t>(d);
        case DepthFormat::D24:
            return static_cast<std::uint32_t>(std::lround(double(d) * double((1u << 24) - 1)));
        case DepthFormat::D16:
            return static_cast<std::uint32_t>(std::lround(double(d) * double((1u << 16) - 1)));
    }
    return 0;
}

float DepthBuffer::decode(std::uint32_t stored) const {
    switch (format_) {
        case DepthFormat::D32F:
            return std::bit_cast<float>(stored);
        case DepthFormat::D24:
            return static_cast<float>(double(stored) / double((1u << 24) - 1));
        case DepthFormat::D16:
            return static_cast<float>(double(stored) / double((1u << 16) - 1));
    }
    return 1.0f;
}

bool parse_depth_format(std::string_view text, DepthFormat& out) {
    if (text == "d32f")
        out = DepthFormat::D32F;
    else if (text == "d24")
        out = DepthFormat::D24;
    else if (text == "d16")
        out = DepthFormat::D16;
    else
        return false;
    return true;
}

bool parse_compare_func(std::string_view text, CompareFunc& out) {
    static constexpr std::pair<std::string_view, CompareFunc> names[] = {
        {"never", CompareFunc::Never},       {"less", CompareFunc::Less},
        {"lequal", CompareFunc::LessEqual},  {"equal", CompareFunc::Equal},
        {"notequal", CompareFunc::NotEqual}, {"gequal", CompareFunc::GreaterEqual},
        {"greater", CompareFunc::Greater},   {"always", CompareFunc::Always}};
    for (const auto& [name, value] : names)
        if (text == name) {
            out = value;
            return true;
        }
    return false;
}

}  // namespace zraster
