// APNG: IHDR, acTL, then per frame an fcTL and the image data (IDAT for the first frame, which
// is also the still image, fdAT after), IEND. Each frame is a whole image (no offsets, no
// disposal or blending tricks): simple, and small enough for slide-sized pictures.
#include "apng_encode.hpp"

#include <libdeflate.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace zraster::cli {
namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

void put_u16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(std::uint8_t(v >> 8));
    out.push_back(std::uint8_t(v));
}

void put_chunk(std::vector<std::uint8_t>& out, const char* type,
               const std::vector<std::uint8_t>& data) {
    put_u32(out, std::uint32_t(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    put_u32(out, std::uint32_t(libdeflate_crc32(0, out.data() + start, out.size() - start)));
}

// The zlib stream of an image's rows, each behind filter byte 0 (none).
std::vector<std::uint8_t> compressed_rows(const RgbaImage& image, libdeflate_compressor* c) {
    const std::size_t row = std::size_t(image.width) * 4;
    std::vector<std::uint8_t> raw;
    raw.reserve((row + 1) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        raw.push_back(0);
        const auto* first = image.pixels.data() + std::size_t(y) * row;
        raw.insert(raw.end(), first, first + row);
    }
    std::vector<std::uint8_t> out(libdeflate_zlib_compress_bound(c, raw.size()));
    out.resize(libdeflate_zlib_compress(c, raw.data(), raw.size(), out.data(), out.size()));
    return out;
}

}  // namespace

std::vector<std::uint8_t> encode_apng(const std::vector<RgbaImage>& frames, int delay_ms) {
    if (frames.empty()) throw std::invalid_argument("encode_apng: no frames");
    const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> c(
        libdeflate_alloc_compressor(9), &libdeflate_free_compressor);
    if (!c) throw std::bad_alloc();
    const int w = frames[0].width, h = frames[0].height;
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> header;
    put_u32(header, std::uint32_t(w));
    put_u32(header, std::uint32_t(h));
    header.insert(header.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA, no interlace
    put_chunk(out, "IHDR", header);
    std::vector<std::uint8_t> animation;
    put_u32(animation, std::uint32_t(frames.size()));
    put_u32(animation, 0);  // loop forever
    put_chunk(out, "acTL", animation);
    std::uint32_t sequence = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].width != w || frames[i].height != h)
            throw std::invalid_argument("encode_apng: frames of different sizes");
        std::vector<std::uint8_t> control;
        put_u32(control, sequence++);
        put_u32(control, std::uint32_t(w));
        put_u32(control, std::uint32_t(h));
        put_u32(control, 0);  // x offset
        put_u32(control, 0);  // y offset
        put_u16(control, std::uint16_t(delay_ms));
        put_u16(control, 1000);
        control.push_back(0);  // dispose: none
        control.push_back(0);  // blend: source (the frame replaces what was there)
        put_chunk(out, "fcTL", control);
        std::vector<std::uint8_t> data = compressed_rows(frames[i], c.get());
        if (i == 0) {
            put_chunk(out, "IDAT", data);
        } else {
            std::vector<std::uint8_t> frame_data;
            put_u32(frame_data, sequence++);
            frame_data.insert(frame_data.end(), data.begin(), data.end());
            put_chunk(out, "fdAT", frame_data);
        }
    }
    put_chunk(out, "IEND", {});
    return out;
}

}  // namespace zraster::cli
