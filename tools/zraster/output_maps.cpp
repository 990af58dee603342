#include "output_maps.hpp"

#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace zraster::cli {

std::string lower_extension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e;
}

void check_output(OutputFiles& outputs, const std::string& path,
                  std::initializer_list<const char*> extensions, const char* option) {
    if (path.empty()) return;
    bool ok = false;
    std::string names;
    for (const char* e : extensions) {
        ok |= lower_extension(path) == e;
        names += names.empty() ? e : std::string(" or ") + e;
    }
    if (!ok) throw InputError(option, "'" + path + "' must end in " + names);
    outputs.check(path, option);
}

namespace {

std::uint8_t unorm8(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

std::vector<std::uint8_t> encode_depth_map(const std::string& path, const RenderTargets& t) {
    const std::string ext = lower_extension(path);
    if (ext == ".npy") return encode_npy(t.width, t.height, std::span<const float>(t.depth));
    if (ext != ".png") throw InputError(path, "depth output must end in .npy or .png");
    std::vector<std::uint16_t> gray(t.depth.size());
    for (std::size_t i = 0; i < gray.size(); ++i)
        gray[i] =
            static_cast<std::uint16_t>(std::lround(std::clamp(t.depth[i], 0.0f, 1.0f) * 65535.0f));
    return encode_png16_gray(t.width, t.height, gray);
}

std::vector<std::uint8_t> encode_normal_map(const std::string& path, const RenderTargets& t) {
    if (lower_extension(path) != ".png") throw InputError(path, "normal output must end in .png");
    std::vector<std::uint8_t> rgb(t.normal.size() * 3);
    for (std::size_t i = 0; i < t.normal.size(); ++i) {
        const glm::vec3 n = t.normal[i];
        const bool empty = n == glm::vec3(0.0f);
        for (int c = 0; c < 3; ++c)
            rgb[i * 3 + std::size_t(c)] = empty ? 0 : unorm8(n[c] * 0.5f + 0.5f);
    }
    return encode_png8(t.width, t.height, 3, rgb);
}

std::vector<std::uint8_t> encode_id_map(const std::string& path, const RenderTargets& t,
                                        const std::vector<std::int64_t>& instance_first_triangle) {
    const std::string ext = lower_extension(path);
    if (ext != ".npy" && ext != ".png")
        throw InputError(path, "id output must end in .npy or .png");
    std::vector<std::int32_t> ids(t.primitive_id.size(), -1);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (t.instance_id[i] < 0) continue;
        const std::int64_t id =
            instance_first_triangle[std::size_t(t.instance_id[i])] + t.primitive_id[i];
        ids[i] = static_cast<std::int32_t>(std::min<std::int64_t>(id, INT32_MAX));
    }
    if (ext == ".npy") return encode_npy(t.width, t.height, std::span<const std::int32_t>(ids));
    std::vector<std::uint8_t> rgb(ids.size() * 3, 0);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (ids[i] < 0) continue;
        // A multiplicative hash spreads neighbouring ids over distinct colors.
        std::uint32_t h = static_cast<std::uint32_t>(ids[i]) * 2654435761u;
        h ^= h >> 15;
        rgb[i * 3 + 0] = static_cast<std::uint8_t>(64 + (h & 0xff) % 192);
        rgb[i * 3 + 1] = static_cast<std::uint8_t>(64 + ((h >> 8) & 0xff) % 192);
        rgb[i * 3 + 2] = static_cast<std::uint8_t>(64 + ((h >> 16) & 0xff) % 192);
    }
    return encode_png8(t.width, t.height, 3, rgb);
}

}  // namespace zraster::cli
