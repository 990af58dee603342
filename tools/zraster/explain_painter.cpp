// `zraster explain painter`: polygons in painting order, the moved and split ones outlined.
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <set>
#include <utility>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

using PolygonKey = std::pair<std::int32_t, std::int32_t>;  // instance, primitive

Rgba byte_color(const glm::vec3& c) {
    const auto b = [](float v) {
        return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    return {b(c.x), b(c.y), b(c.z), 255};
}

// Bars of how the comparisons were settled.
Figure resolution_chart(const PainterStats& s) {
    const char* names[] = {
        "depth extents",           "x extents",           "y extents", "P behind Q's plane",
        "Q in front of P's plane", "projections disjoint"};
    std::vector<std::pair<std::string, std::uint64_t>> bars;
    for (std::size_t i = 0; i < 6; ++i) bars.emplace_back(names[i], s.resolved_by[i]);
    bars.emplace_back("swaps (Q moved ahead)", s.swaps);
    bars.emplace_back("splits", s.splits);
    std::uint64_t most = 1;
    for (const auto& b : bars) most = std::max(most, b.second);
    Figure f(520, 30 + 22 * int(bars.size()));
    f.text({10, 8}, fmt::format("{} comparisons, settled by:", s.comparisons));
    for (std::size_t i = 0; i < bars.size(); ++i) {
        const double y = 28 + 22.0 * double(i);
        const double length = 250.0 * double(bars[i].second) / double(most);
        f.rect(170, y, 170 + std::max(length, 1.0), y + 14,
               FigureStyle{i < 6 ? Rgba{90, 140, 220, 255} : Rgba{220, 90, 60, 255}});
        f.text({10, y + 2}, bars[i].first);
        f.text({176 + length, y + 2}, std::to_string(bars[i].second));
    }
    return f;
}

}  // namespace

void explain_painter(const ExplainInput& in, ExplainOutput& out) {
    std::vector<ScreenPolygon> polygons = project_scene(in.scene, in.options);
    const std::size_t input = polygons.size();
    std::set<PolygonKey> moved, split;
    PainterObserver observer;
    observer.swapped = [&](const ScreenPolygon& p, const ScreenPolygon&) {
        moved.insert({p.instance, p.primitive});
    };
    observer.split = [&](const ScreenPolygon& p, const glm::dvec4&) {
        split.insert({p.instance, p.primitive});
    };
    PainterOptions options;
    options.observer = &observer;
    options.progress = in.options.progress;
    options.max_comparisons = painter_comparison_budget(in.options.limits, input);
    const PainterResult result =
        painter_sort(std::move(polygons), Viewport{in.options.width, in.options.height}, options);
    const glm::vec3 bg = in.options.background * 255.0f;
    const Rgba background{std::uint8_t(bg.x), std::uint8_t(bg.y), std::uint8_t(bg.z), 255};
    const std::vector<std::size_t> counts = frame_counts(result.order.size(), in.step);
    check_explain_pixels(counts.size(),
                         std::uint64_t(in.options.width) * std::uint64_t(in.options.height),
                         in.max_pixels, fmt::format("explain painter's {} frames", counts.size()),
                         "or raise --step");
    std::vector<RgbaImage> frames;
    for (const std::size_t n : counts) {
        in.report("explain painter: painting the frames",
                  double(frames.size()) / double(counts.size()));
        RgbaImage image(in.options.width, in.options.height, background);
        for (std::size_t i = 0; i < n; ++i) {
            const ScreenPolygon& p = result.order[i];
            const std::vector<glm::dvec2> points = window_points(p);
            fill_polygon(image, points, byte_color(p.color));
            const PolygonKey key{p.instance, p.primitive};
            if (split.count(key))
                outline_polygon(image, points, Rgba{230, 30, 30, 255});
            else if (moved.count(key))
                outline_polygon(image, points, Rgba{250, 210, 0, 255});
        }
        frames.push_back(captioned(
            image, fmt::format("painted {} of {} polygons (from {} projected), back to front\n"
                               "red outline: pieces of split polygons; yellow: moved ahead",
                               n, result.order.size(), input)));
    }
    in.report("explain painter: encoding the pictures", 0.0);
    for (std::size_t i = 0; i < frames.size(); ++i)
        out.still(fmt::format("painter-{:02}", i + 1), frames[i],
                  fmt::format("painting order, frame {} of {}", i + 1, frames.size()));
    out.animation("painter-animation", frames, 700, "the painting order in sequence");
    out.figure("painter-tests", resolution_chart(result.stats),
               "which overlap test settled each comparison, and how many moves and splits the "
               "conflicts needed");
}

}  // namespace zraster::cli
