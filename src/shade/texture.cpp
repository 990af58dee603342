// Mipmapped textures: Williams 1983, "Pyramidal Parametrics" (SIGGRAPH '83). Level of detail and
// the nearest / linear / linear-mipmap-linear filters as in the OpenGL 4.6 specification,
// section 8.14 (texel centers at half-integers, repeat wrapping).
#include <zraster/texture.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace zraster {

namespace {

constexpr float kByteToUnit = 1.0f / 255.0f;

// One output texel's overlap with the input texels along one axis of a box-filter reduction.
// Input texel s covers [s * out_size, (s + 1) * out_size) and output texel x covers
// [x * in_size, (x + 1) * in_size) in units of 1 / out_size texels, so overlaps are integers:
// an odd size is filtered by exact area weights (a 3-texel row halves to one texel averaging all
// three), the mean of the image is kept at every level.
struct Footprint {
    int first, last;  // input texels [first, last]
};

// In 64 bits: in_size * out_size exceeds int for textures wider than 46341 texels.
Footprint footprint(std::int64_t x, std::int64_t in_size, std::int64_t out_size) {
    return {int(x * in_size / out_size), int(((x + 1) * in_size - 1) / out_size)};
}

std::uint64_t overlap(std::int64_t s, std::int64_t x, std::int64_t in_size, std::int64_t out_size) {
    const std::int64_t lo = std::max(s * out_size, x * in_size);
    const std::int64_t hi = std::min((s + 1) * out_size, (x + 1) * in_size);
    return std::uint64_t(hi - lo);
}

std::vector<std::uint8_t> reduce(std::span<const std::uint8_t> in, int w, int h, int nw, int nh) {
    std::vector<std::uint8_t> out(std::size_t(nw) * std::size_t(nh) * 4);
    // Weights sum to w * h per output texel (at most 2^31 texels * 255 fits in 64 bits).
    const std::uint64_t total = std::uint64_t(w) * std::uint64_t(h);
    for (int y = 0; y < nh; ++y) {
        const Footprint fy = footprint(y, h, nh);
        for (int x = 0; x < nw; ++x) {
            const Footprint fx = footprint(x, w, nw);
            std::uint64_t sum[4] = {0, 0, 0, 0};
            for (int sy = fy.first; sy <= fy.last; ++sy) {
                const std::uint64_t wy = overlap(sy, y, h, nh);
                for (int sx = fx.first; sx <= fx.last; ++sx) {
                    const std::uint64_t weight = wy * overlap(sx, x, w, nw);
                    const std::uint8_t* t = &in[(std::size_t(sy) * std::size_t(w) + sx) * 4];
                    for (int c = 0; c < 4; ++c) sum[c] += weight * t[c];
                }
            }
            std::uint8_t* o = &out[(std::size_t(y) * std::size_t(nw) + x) * 4];
            for (int c = 0; c < 4; ++c) o[c] = std::uint8_t((sum[c] + total / 2) / total);
        }
    }
    return out;
}

// Repeat wrapping of a texture coordinate to [0, 1]; non-finite coordinates sample the origin
// rather than turning into undefined integer conversions.
float wrap_unit(float u) {
    const float f = u - std::floor(u);
    return f >= 0.0f && f <= 1.0f ? f : 0.0f;
}

glm::vec4 lerp4(const glm::vec4& a, const glm::vec4& b, float t) {
    return a + (b - a) * t;
}

}  // namespace

Texture::Texture(int width, int height, std::span<const std::uint8_t> rgba, int max_side) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("Texture: non-positive size");
    const std::size_t bytes = std::size_t(width) * std::size_t(height) * 4;
    if (rgba.size() < bytes) throw std::invalid_argument("Texture: rgba buffer too short");
    // The levels too large for max_side, each reduced from the one before and dropped.
    std::vector<std::uint8_t> reduced;
    while (max_side > 0 && (width > max_side || height > max_side)) {
        const int nw = std::max(1, width / 2), nh = std::max(1, height / 2);
        reduced =
            reduce(reduced.empty() ? rgba.first(bytes) : std::span<const std::uint8_t>(reduced),
                   width, height, nw, nh);
        width = nw;
        height = nh;
    }
    levels_.push_back({width, height,
                       reduced.empty()
                           ? std::vector<std::uint8_t>(rgba.begin(), rgba.begin() + bytes)
                           : std::move(reduced)});
    const std::vector<std::uint8_t>& top = levels_.front().rgba;
    for (std::size_t i = 3; i < top.size() && !translucent_; i += 4) translucent_ = top[i] != 255;
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& in = levels_.back();
        const int nw = std::max(1, in.width / 2), nh = std::max(1, in.height / 2);
        Level next{nw, nh, reduce(in.rgba, in.width, in.height, nw, nh)};
        levels_.push_back(std::move(next));
    }
}

int Texture::width() const {
    return levels_.front().width;
}
int Texture::height() const {
    return levels_.front().height;
}
int Texture::levels() const {
    return int(levels_.size());
}
int Texture::level_width(int level) const {
    return levels_.at(std::size_t(level)).width;
}
int Texture::level_height(int level) const {
    return levels_.at(std::size_t(level)).height;
}

std::span<const std::uint8_t> Texture::level_rgba(int level) const {
    return levels_.at(std::size_t(level)).rgba;
}

glm::vec4 Texture::texel(int level, int x, int y) const {
    const Level& l = levels_[std::size_t(std::clamp(level, 0, levels() - 1))];
    x %= l.width;
    y %= l.height;
    if (x < 0) x += l.width;
    if (y < 0) y += l.height;
    const std::uint8_t* t = &l.rgba[(std::size_t(y) * std::size_t(l.width) + x) * 4];
    return glm::vec4(t[0], t[1], t[2], t[3]) * kByteToUnit;
}

float Texture::level_of_detail(glm::vec2 duv_dx, glm::vec2 duv_dy) const {
    const glm::vec2 size{float(width()), float(height())};
    const float rho = std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
    return std::log2(rho);  // -inf for a zero footprint: clamped to level 0 by the samplers
}

glm::vec4 Texture::sample_nearest(glm::vec2 uv, int level) const {
    const Level& l = levels_[std::size_t(std::clamp(level, 0, levels() - 1))];
    // The texel containing (u w, v h); u = 1 (or a rounding up to it) wraps to texel 0.
    int x = int(wrap_unit(uv.x) * float(l.width));
    int y = int(wrap_unit(uv.y) * float(l.height));
    if (x >= l.width) x = 0;
    if (y >= l.height) y = 0;
    const std::uint8_t* t = &l.rgba[(std::size_t(y) * std::size_t(l.width) + x) * 4];
    return glm::vec4(t[0], t[1], t[2], t[3]) * kByteToUnit;
}

glm::vec4 Texture::sample_bilinear(glm::vec2 uv, int level) const {
    const Level& l = levels_[std::size_t(std::clamp(level, 0, levels() - 1))];
    // Texel centers at half-integers. Wrapping u first keeps the fraction precise for large u and
    // bounds the texel indices to [-1, size], so wrapping them needs no division.
    const float tx = wrap_unit(uv.x) * float(l.width) - 0.5f;
    const float ty = wrap_unit(uv.y) * float(l.height) - 0.5f;
    const float fx0 = std::floor(tx), fy0 = std::floor(ty);
    const float ax = tx - fx0, ay = ty - fy0;
    int x0 = int(fx0), y0 = int(fy0);
    int x1 = x0 + 1, y1 = y0 + 1;
    if (x0 < 0) x0 += l.width;
    if (y0 < 0) y0 += l.height;
    if (x1 >= l.width) x1 -= l.width;
    if (y1 >= l.height) y1 -= l.height;
    const std::uint8_t* data = l.rgba.data();
    const std::size_t row0 = std::size_t(y0) * std::size_t(l.width);
    const std::size_t row1 = std::size_t(y1) * std::size_t(l.width);
    auto fetch = [data](std::size_t index) {
        const std::uint8_t* t = data + index * 4;
        return glm::vec4(t[0], t[1], t[2], t[3]);
    };
    const glm::vec4 top = lerp4(fetch(row0 + x0), fetch(row0 + x1), ax);
    const glm::vec4 bottom = lerp4(fetch(row1 + x0), fetch(row1 + x1), ax);
    return lerp4(top, bottom, ay) * kByteToUnit;
}

glm::vec4 Texture::sample_trilinear(glm::vec2 uv, float lod) const {
    const float max_level = float(levels() - 1);
    // NaN (a degenerate footprint) goes to level 0, as does -inf (magnification).
    lod = lod > 0.0f ? std::min(lod, max_level) : 0.0f;
    const float base = std::floor(lod);
    const float blend = lod - base;
    const int level = int(base);
    if (blend == 0.0f) return sample_bilinear(uv, level);
    return lerp4(sample_bilinear(uv, level), sample_bilinear(uv, level + 1), blend);
}

glm::vec4 Texture::sample(glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy,
                          TextureFilter filter) const {
    switch (filter) {
        case TextureFilter::Nearest:
            return sample_nearest(uv, 0);
        case TextureFilter::Bilinear:
            return sample_bilinear(uv, 0);
        case TextureFilter::Trilinear:
            return sample_trilinear(uv, level_of_detail(duv_dx, duv_dy));
    }
    return sample_bilinear(uv, 0);
}

Texture make_checkerboard_texture(int squares, int cell, glm::u8vec4 a, glm::u8vec4 b) {
    if (squares <= 0 || cell <= 0)
        throw std::invalid_argument("make_checkerboard_texture: non-positive size");
    const int size = squares * cell;
    std::vector<std::uint8_t> rgba(std::size_t(size) * std::size_t(size) * 4);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::u8vec4 c = ((x / cell + y / cell) & 1) ? b : a;  // a at the top left
            std::uint8_t* t = &rgba[(std::size_t(y) * std::size_t(size) + x) * 4];
            for (int k = 0; k < 4; ++k) t[k] = c[k];
        }
    }
    return Texture(size, size, rgba);
}

}  // namespace zraster
