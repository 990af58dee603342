// `zraster explain warnock`: the subdivision level by level, regions colored by their outcome.
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include "bitmap_text.hpp"
#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

struct RegionRecord {
    PixelRegion region;
    std::size_t level;
    WarnockRegionOutcome outcome;
};

Rgba outcome_color(WarnockRegionOutcome o) {
    switch (o) {
        case WarnockRegionOutcome::Empty:
            return {150, 150, 150, 110};
        case WarnockRegionOutcome::Single:
            return {40, 200, 60, 110};
        case WarnockRegionOutcome::Surrounded:
            return {40, 110, 240, 110};
        case WarnockRegionOutcome::Pixel:
            return {230, 40, 230, 150};
        case WarnockRegionOutcome::Subdivided:
            return {240, 40, 30, 110};
    }
    return {};
}

RgbaImage level_picture(const RgbaImage& base, const std::vector<RegionRecord>& records,
                        std::size_t level) {
    RgbaImage image = base;
    fill_rect(image, 0, 0, image.width, image.height, Rgba{255, 255, 255, 130});  // faded
    for (const RegionRecord& r : records) {
        const bool leaf = r.outcome != WarnockRegionOutcome::Subdivided;
        if (r.level > level || (!leaf && r.level != level)) continue;
        const PixelRegion& p = r.region;
        fill_rect(image, p.x0, p.y0, p.x1, p.y1, outcome_color(r.outcome));
        if (p.x1 - p.x0 > 2)
            outline_polygon(
                image,
                std::vector<glm::dvec2>{
                    {p.x0, p.y0}, {p.x1 - 1, p.y0}, {p.x1 - 1, p.y1 - 1}, {p.x0, p.y1 - 1}},
                Rgba{0, 0, 0, 90});
    }
    return image;
}

}  // namespace

void explain_warnock(const ExplainInput& in, ExplainOutput& out) {
    // Counted before the subdivision: halving the larger side down to one pixel takes at most
    // 1 + ceil(log2(side)) levels (any edge in the scene reaches the last), and a picture each,
    // and the result.
    std::size_t most_levels = 1;
    for (int side = std::max(in.options.width, in.options.height); side > 1; side -= side / 2)
        ++most_levels;
    check_explain_pixels(
        most_levels + 1, std::uint64_t(in.options.width) * std::uint64_t(in.options.height),
        in.max_pixels,
        fmt::format("explain warnock's {} pictures (levels and result)", most_levels + 1));
    const std::vector<ScreenPolygon> polygons = project_scene(in.scene, in.options);
    std::vector<RegionRecord> records;
    WarnockObserver observer;
    observer.region = [&](const PixelRegion& r, std::size_t level, WarnockRegionOutcome o) {
        records.push_back({r, level, o});
    };
    const WarnockResult result = warnock_render(
        polygons, in.options, effective_camera(in.scene, in.options), &observer, &in.scene);
    const RgbaImage base = color_image(result.targets);
    const std::size_t levels = result.stats.regions_per_level.size();
    std::vector<RgbaImage> frames;
    for (std::size_t level = 0; level < levels; ++level) {
        in.report("explain warnock: drawing the levels", double(level) / double(levels));
        std::size_t counts[5] = {};
        for (const RegionRecord& r : records)
            if (r.level == level) ++counts[std::size_t(r.outcome)];
        frames.push_back(captioned(
            level_picture(base, records, level),
            fmt::format("level {}: {} regions. gray empty {}, green single polygon {},\n"
                        "blue surrounded {}, magenta pixel {}, red too complex (subdivided) {}",
                        level, result.stats.regions_per_level[level], counts[0], counts[1],
                        counts[2], counts[3], counts[4])));
    }
    for (std::size_t i = 0; i < frames.size(); ++i) {
        in.report("explain warnock: encoding the pictures", double(i) / double(frames.size()));
        out.still(fmt::format("warnock-level-{:02}", i), frames[i],
                  fmt::format("the regions of subdivision level {} and the leaves above it", i));
    }
    in.report("explain warnock: encoding the animation", 0.0);
    out.animation("warnock-animation", frames, 800, "the subdivision level by level");
    out.still("warnock-result", base, "the image Warnock's algorithm drew");
}

}  // namespace zraster::cli
