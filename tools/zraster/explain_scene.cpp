// Helpers of the 3D explain pictures.
#include "explain_scene.hpp"

#include <algorithm>
#include <cmath>

#include "bitmap_text.hpp"

namespace zraster::cli {

RgbaImage color_image(const RenderTargets& targets) {
    RgbaImage image(targets.width, targets.height);
    image.pixels = targets.color;
    return image;
}

RgbaImage depth_image(const RenderTargets& targets, float clear_value) {
    RgbaImage image(targets.width, targets.height);
    float lo = 1.0f, hi = 0.0f;  // the range of the stored depths, for contrast
    for (const float d : targets.depth)
        if (d != clear_value) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    const float range = hi > lo ? hi - lo : 1.0f;
    for (std::size_t i = 0; i < targets.depth.size(); ++i) {
        const float d = targets.depth[i];
        const auto gray = d == clear_value
                              ? std::uint8_t(0)
                              : std::uint8_t(std::lround(255.0f - 200.0f * (d - lo) / range));
        image.pixels[i * 4] = image.pixels[i * 4 + 1] = image.pixels[i * 4 + 2] = gray;
    }
    return image;
}

RgbaImage side_by_side(const RgbaImage& left, const RgbaImage& right) {
    RgbaImage image(left.width + right.width + 4, std::max(left.height, right.height),
                    Rgba{255, 255, 255, 255});
    paste(image, left, 0, 0);
    paste(image, right, left.width + 4, 0);
    return image;
}

namespace {

// The text with lines broken between words to at most `columns` characters.
std::string wrapped(const std::string& text, std::size_t columns) {
    std::string out, line, word;
    const auto end_word = [&] {
        if (!line.empty() && line.size() + 1 + word.size() > columns) {
            out += line + '\n';
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        word.clear();
    };
    for (const char c : text + '\n') {
        if (c != ' ' && c != '\n') {
            word += c;
            continue;
        }
        end_word();
        if (c == '\n') {
            out += line + '\n';
            line.clear();
        }
    }
    out.pop_back();
    return out;
}

}  // namespace

RgbaImage captioned(const RgbaImage& image, const std::string& caption) {
    // The bitmap font's characters are 6 pixels wide at scale 1.
    const std::string text = wrapped(caption, std::size_t(std::max(8, (image.width - 8) / 6)));
    const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
    RgbaImage out(image.width, image.height + lines * kTextLineHeight + 6,
                  Rgba{255, 255, 255, 255});
    paste(out, image, 0, 0);
    draw_text(out, 4, image.height + 4, text, Rgba{0, 0, 0, 255});
    return out;
}

Rgba palette(std::size_t index) {
    // HSV with golden-angle hue steps, saturation and value high enough to read on white.
    const double h = std::fmod(double(index) * 137.508, 360.0) / 60.0;
    const double s = 0.65, v = 0.92;
    const double c = v * s, x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0)), m = v - c;
    double r = 0, g = 0, b = 0;
    switch (int(h)) {
        case 0:
            r = c;
            g = x;
            break;
        case 1:
            r = x;
            g = c;
            break;
        case 2:
            g = c;
            b = x;
            break;
        case 3:
            g = x;
            b = c;
            break;
        case 4:
            r = x;
            b = c;
            break;
        default:
            r = c;
            b = x;
            break;
    }
    const auto byte = [m](double t) { return std::uint8_t(std::lround((t + m) * 255.0)); };
    return {byte(r), byte(g), byte(b), 255};
}

std::vector<glm::dvec2> window_points(const ScreenPolygon& polygon) {
    std::vector<glm::dvec2> points;
    for (const PolygonVertex& v : polygon.vertices) points.emplace_back(v.window.x, v.window.y);
    return points;
}

std::optional<glm::dvec2> project_point(const Camera& camera, int width, int height,
                                        const glm::dvec3& world) {
    const glm::dvec4 clip =
        glm::dmat4(camera.view_projection(double(width) / double(height))) * glm::dvec4(world, 1.0);
    if (!(clip.w > 1e-9)) return std::nullopt;
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return glm::dvec2((ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height);
}

std::size_t frame_step(std::size_t items, int step) {
    // At most 64 frames: an animation longer than that says nothing more.
    const std::size_t fewest = std::max<std::size_t>(1, (items + 63) / 64);
    if (step > 0) return std::max(std::size_t(step), fewest);
    return std::max<std::size_t>(1, (items + 7) / 8);
}

std::vector<std::size_t> frame_counts(std::size_t items, int step) {
    std::vector<std::size_t> counts;
    const std::size_t k = frame_step(items, step);
    for (std::size_t n = k; n < items; n += k) counts.push_back(n);
    counts.push_back(items);
    return counts;
}

}  // namespace zraster::cli
