// Reading 8-bit images through stb_image.
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include "io/image_decode.hpp"
#include "io/read_file.hpp"
#include "io/text_util.hpp"

#include <stb/stb_image.h>

#include <climits>
#include <cstdlib>
#include <memory>

namespace zraster {

std::optional<io::ImageSize> io::encoded_image_size(std::span<const std::uint8_t> bytes) {
    if (bytes.empty() || bytes.size() > static_cast<std::size_t>(INT_MAX)) return std::nullopt;
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                              &channels) == 0)
        return std::nullopt;
    return ImageSize{width, height};
}

ImageRGBA8 io::decode_image_rgba8(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.empty()) throw InputError(name, "empty file");
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw InputError(name, "image file too large");
    // Rows top to bottom regardless of what another caller set globally in stb.
    stbi_set_flip_vertically_on_load_thread(0);
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
        stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                              &channels, 4),
        &stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw InputError(name, std::string("cannot decode image: ") +
                                   (reason ? io::one_line(reason) : "unknown error"));
    }
    ImageRGBA8 image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * height * 4);
    return image;
}

ImageRGBA8 read_image_rgba8(const std::filesystem::path& path) {
    return io::decode_image_rgba8(io::read_file_bytes(path), path.string());
}

}  // namespace zraster
