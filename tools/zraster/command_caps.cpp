#include "command_caps.hpp"

#include <zraster/error.hpp>

#include <fmt/format.h>

#include <charconv>
#include <string_view>

namespace zraster::cli {

namespace {
CommandCaps g_caps;

// The leading decimal number of `text`, saturated; 0 for none.
std::uint64_t leading_number(std::string_view text) {
    std::uint64_t n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error == std::errc::result_out_of_range) return UINT64_MAX;
    return end == text.data() ? 0 : n;
}
}  // namespace

void set_command_caps(const CommandCaps& caps) {
    g_caps = caps;
}

const CommandCaps& command_caps() {
    return g_caps;
}

void check_samples_cap(const std::string& option, int width, int height, int aa) {
    if (g_caps.max_samples == 0) return;
    const std::uint64_t samples =
        std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(aa) * std::uint64_t(aa);
    if (samples > g_caps.max_samples)
        throw InputError(option, fmt::format("{}x{} with {}x{} samples a pixel is {} samples, more "
                                             "than the {} this run allows",
                                             width, height, aa, aa, samples, g_caps.max_samples));
}

void check_scene_cap(const std::string& spec) {
    if (g_caps.max_scene_triangles == 0) return;
    const std::string_view s(spec);
    const std::size_t colon = s.find(':');
    if (colon == std::string_view::npos) return;
    const std::string_view kind = s.substr(0, colon), rest = s.substr(colon + 1);
    std::uint64_t triangles = 0;
    if (kind == "sphere" || kind == "soup") {
        triangles = leading_number(rest);
    } else if (kind == "city") {
        const std::uint64_t boxes = leading_number(rest);
        triangles = boxes > UINT64_MAX / 12 ? UINT64_MAX : 12 * boxes;
    } else if (kind == "building") {
        const std::uint64_t rows = leading_number(rest);
        const std::size_t x = rest.find('x');
        const std::uint64_t columns =
            x == std::string_view::npos ? 0 : leading_number(rest.substr(x + 1));
        // About 200 triangles a room (walls with doorways, floor, crates).
        triangles =
            rows != 0 && columns > UINT64_MAX / 200 / rows ? UINT64_MAX : 200 * rows * columns;
    }
    if (triangles > g_caps.max_scene_triangles)
        throw InputError(spec, fmt::format("about {} triangles, more than the {} this run allows",
                                           triangles, g_caps.max_scene_triangles));
}

int capped_threads(const std::string& option, int threads) {
    if (g_caps.max_threads == 0 || threads <= g_caps.max_threads) return threads;
    fmt::print(stderr, "warning: {} {} is more than the {} this run allows; using {}\n", option,
               threads, g_caps.max_threads, g_caps.max_threads);
    return g_caps.max_threads;
}

}  // namespace zraster::cli
