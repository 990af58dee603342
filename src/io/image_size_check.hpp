// Argument checks shared by the image and array writers.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace zraster::io {

// Throws std::invalid_argument unless width, height > 0 and count == width * height * channels.
inline void check_image_size(const char* what, int width, int height, int channels,
                             std::size_t count) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument(std::string(what) + ": width and height must be positive");
    const std::size_t expected = static_cast<std::size_t>(width) *
                                 static_cast<std::size_t>(height) *
                                 static_cast<std::size_t>(channels);
    if (count != expected)
        throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(expected) +
                                    " values, got " + std::to_string(count));
}

}  // namespace zraster::io
