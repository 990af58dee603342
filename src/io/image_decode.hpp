// Decoding 8-bit images (PNG, JPEG, BMP, TGA, ... through stb_image) held in memory, and reading
// the size an image declares before decoding it, so that a texture budget is checked before the
// pixels are allocated.
#pragma once
#include <zraster/image_io.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace zraster::io {

struct ImageSize {
    int width = 0, height = 0;
};

// The width and height in the image's header; nullopt when the header cannot be read (decoding
// then reports why).
std::optional<ImageSize> encoded_image_size(std::span<const std::uint8_t> bytes);

// RGBA8, rows top to bottom. Throws InputError(name, "cannot decode image: <stb's reason>").
ImageRGBA8 decode_image_rgba8(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace zraster::io
