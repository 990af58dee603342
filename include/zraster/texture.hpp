// RGBA textures with a full mipmap chain, sampled with nearest, bilinear or trilinear filtering.
//
// Texels are stored as RGBA8 and returned as floats in [0, 1]. Coordinates: u to the right,
// v downwards (v = 0 is the image's first row), wrapping by repetition. Level 0 is the image; each
// further level halves the size (box filter, odd sizes rounded down, minimum 1) down to 1x1.
#pragma once
#include <glm/glm.hpp>
#include <zraster/export.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zraster {

enum class TextureFilter { Nearest, Bilinear, Trilinear };

class ZRASTER_API Texture {
  public:
    // rgba holds width*height*4 bytes, rows top to bottom. Builds the mip chain. With max_side
    // > 0, the levels wider or taller than max_side are left out: the texture starts at the
    // first level of the chain that fits (the same box filter), so a huge image costs its
    // reduced size (and the reductions down to it) rather than its full chain.
    // Throws std::invalid_argument for non-positive sizes or a short buffer.
    Texture(int width, int height, std::span<const std::uint8_t> rgba, int max_side = 0);

    int width() const;
    int height() const;
    int levels() const;
    int level_width(int level) const;
    int level_height(int level) const;

    // The RGBA8 bytes of one level (level_width * level_height * 4, rows top to bottom).
    std::span<const std::uint8_t> level_rgba(int level) const;

    // One texel of one level (x, y wrapped), as floats in [0, 1].
    glm::vec4 texel(int level, int x, int y) const;

    // Level of detail from the screen-space derivatives of (u, v): log2 of the longer of the two
    // texel-space footprints, as in the OpenGL specification (clamped to [0, levels-1] by sample).
    float level_of_detail(glm::vec2 duv_dx, glm::vec2 duv_dy) const;

    glm::vec4 sample_nearest(glm::vec2 uv, int level = 0) const;
    glm::vec4 sample_bilinear(glm::vec2 uv, int level = 0) const;
    // Bilinear in the two levels around lod, blended linearly.
    glm::vec4 sample_trilinear(glm::vec2 uv, float lod) const;

    // Sample with the given filter; Nearest and Bilinear use level 0 (no mipmapping).
    glm::vec4 sample(glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, TextureFilter filter) const;

    // Whether a texel of level 0 has an alpha below 255 (then so may any sample).
    bool has_translucent_texels() const { return translucent_; }

  private:
    struct Level {
        int width, height;
        std::vector<std::uint8_t> rgba;
    };
    std::vector<Level> levels_;
    bool translucent_ = false;
};

// A two-colour checkerboard of `squares` x `squares` cells, each `cell` texels wide.
ZRASTER_API Texture make_checkerboard_texture(int squares, int cell, glm::u8vec4 a, glm::u8vec4 b);

}  // namespace zraster
