// PNG output. 8-bit images go through stb_image_write; 16-bit grayscale, which stb cannot write,
// is assembled here (chunks + CRC) around stb's zlib compressor.
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include "io/atomic_write.hpp"
#include "io/image_size_check.hpp"

#include <stb/stb_image_write.h>

#include <array>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string_view>

// Defined by Debian's libstb (stb_image_write's implementation, extern "C" like the rest of its
// API) but only declared inside the header's implementation section. Returns a zlib stream
// (header + deflate + Adler-32) allocated with malloc.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len,
                                             int quality);

namespace zraster {

namespace {

void check_encoder_limit(const std::filesystem::path& path, std::size_t bytes) {
    // stb's encoders index with int.
    if (bytes > static_cast<std::size_t>(INT_MAX) / 2)
        throw std::invalid_argument("PNG " + path.string() + ": image too large to encode");
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    crc = ~crc;
    for (std::uint8_t b : bytes) crc = table[(crc ^ b) & 0xFF] ^ (crc >> 8);
    return ~crc;
}

void put_u32_be(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void put_chunk(std::vector<std::uint8_t>& out, std::string_view type,
               std::span<const std::uint8_t> data) {
    put_u32_be(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type.begin(), type.end());
    out.insert(out.end(), data.begin(), data.end());
    put_u32_be(out, crc32(std::span(out).subspan(start)));
}

}  // namespace

void write_png8(const std::filesystem::path& path, int width, int height, int channels,
                std::span<const std::uint8_t> pixels) {
    if (channels < 1 || channels > 4)
        throw std::invalid_argument("write_png8: channels must be 1, 2, 3 or 4");
    io::check_image_size("write_png8", width, height, channels, pixels.size());
    check_encoder_limit(path, pixels.size());

    std::vector<std::uint8_t> encoded;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &encoded, width, height, channels, pixels.data(),
                                width * channels))
        throw InputError(path.string(), "cannot write: PNG encoding failed");
    io::write_file_atomically(path, encoded);
}

void write_png16_gray(const std::filesystem::path& path, int width, int height,
                      std::span<const std::uint16_t> pixels) {
    io::check_image_size("write_png16_gray", width, height, 1, pixels.size());
    const std::size_t row_bytes = static_cast<std::size_t>(width) * 2;
    check_encoder_limit(path, (row_bytes + 1) * static_cast<std::size_t>(height));

    // Scanlines: a filter byte, then big-endian samples. Filter "Up" (2) stores the difference
    // from the row above, which compresses smooth depth images far better than "None".
    std::vector<std::uint8_t> raw((row_bytes + 1) * static_cast<std::size_t>(height));
    std::vector<std::uint8_t> previous(row_bytes, 0), current(row_bytes);
    for (int y = 0; y < height; ++y) {
        const std::uint16_t* row = pixels.data() + static_cast<std::size_t>(y) * width;
        for (int x = 0; x < width; ++x) {
            current[2 * x] = static_cast<std::uint8_t>(row[x] >> 8);
            current[2 * x + 1] = static_cast<std::uint8_t>(row[x] & 0xFF);
        }
        std::uint8_t* out = raw.data() + static_cast<std::size_t>(y) * (row_bytes + 1);
        out[0] = 2;
        for (std::size_t i = 0; i < row_bytes; ++i)
            out[1 + i] = static_cast<std::uint8_t>(current[i] - previous[i]);
        previous.swap(current);
    }

    int zlib_size = 0;
    std::unique_ptr<unsigned char, decltype(&std::free)> zlib(
        stbi_zlib_compress(raw.data(), static_cast<int>(raw.size()), &zlib_size, 8), &std::free);
    if (!zlib) throw InputError(path.string(), "cannot write: PNG compression failed");

    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<std::uint8_t> header;
    put_u32_be(header, static_cast<std::uint32_t>(width));
    put_u32_be(header, static_cast<std::uint32_t>(height));
    // Bit depth 16, colour type 0 (grayscale), deflate, adaptive filtering, no interlace.
    header.insert(header.end(), {16, 0, 0, 0, 0});
    put_chunk(png, "IHDR", header);
    put_chunk(png, "IDAT", std::span<const std::uint8_t>(zlib.get(), zlib_size));
    put_chunk(png, "IEND", {});
    io::write_file_atomically(path, png);
}

}  // namespace zraster
