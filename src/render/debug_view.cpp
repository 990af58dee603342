#include <zraster/debug_view.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace zraster {

namespace {

struct NamedView {
    DebugView view;
    std::string_view name;
};

constexpr std::array kNamedViews{
    NamedView{DebugView::None, "none"},       NamedView{DebugView::Depth, "depth"},
    NamedView{DebugView::Normals, "normals"}, NamedView{DebugView::Overdraw, "overdraw"},
    NamedView{DebugView::HiZ, "hiz"},         NamedView{DebugView::Tiles, "tiles"},
    NamedView{DebugView::Ids, "ids"},         NamedView{DebugView::Backfaces, "backfaces"},
    NamedView{DebugView::Clipped, "clipped"}, NamedView{DebugView::ZFight, "zfight"},
    NamedView{DebugView::Mip, "mip"},
};

constexpr std::array kViews = [] {
    std::array<DebugView, kNamedViews.size()> views{};
    for (std::size_t i = 0; i < kNamedViews.size(); ++i) views[i] = kNamedViews[i].view;
    return views;
}();

// matplotlib's "plasma" at t = 0, 1/4, 1/2, 3/4, 1.
constexpr std::array<std::array<double, 3>, 5> kScaleStops{{
    {13, 8, 135},
    {126, 3, 168},
    {204, 71, 120},
    {248, 149, 64},
    {240, 249, 33},
}};

// A count or distance as the legend prints it (up to 4 significant digits).
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

std::span<const DebugView> debug_views() {
    return kViews;
}

std::string_view debug_view_name(DebugView view) {
    for (const NamedView& named : kNamedViews)
        if (named.view == view) return named.name;
    return "none";
}

std::string debug_view_names() {
    std::string names;
    for (const NamedView& named : kNamedViews)
        names += (names.empty() ? "" : ", ") + std::string(named.name);
    return names;
}

std::array<std::uint8_t, 3> debug_view_scale_color(double t) {
    t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
    const double at = t * double(kScaleStops.size() - 1);
    const std::size_t i = std::min(std::size_t(at), kScaleStops.size() - 2);
    const double f = at - double(i);
    std::array<std::uint8_t, 3> rgb{};
    for (std::size_t k = 0; k < 3; ++k)
        rgb[k] = static_cast<std::uint8_t>(
            std::lround(kScaleStops[i][k] + (kScaleStops[i + 1][k] - kScaleStops[i][k]) * f));
    return rgb;
}

bool debug_view_has_scale(DebugView view) {
    switch (view) {
        case DebugView::Depth:
        case DebugView::Overdraw:
        case DebugView::HiZ:
        case DebugView::Tiles:
        case DebugView::Mip:
            return true;
        default:
            return false;
    }
}

std::string debug_view_legend(DebugView view, const DebugViewScale& scale) {
    const std::string low = number(scale.low), high = number(scale.high);
    switch (view) {
        case DebugView::None:
            return "";
        case DebugView::Depth:
            return "depth: eye distance " + low + " (yellow) .. " + high + " (blue)";
        case DebugView::Normals:
            return "normals: world normal as color n * 0.5 + 0.5 (x red, y green, z blue)";
        case DebugView::Overdraw:
            return "overdraw: fragments per pixel 1 (blue) .. " + high +
                   " (yellow), log scale; black none";
        case DebugView::HiZ:
            return "hiz: triangle blocks skipped by hierarchical z per 8x8 block 1 (blue) .. " +
                   high + " (yellow), log scale";
        case DebugView::Tiles:
            return "tiles: triangles binned per 64x64 tile 1 (blue) .. " + high +
                   " (yellow), log scale; black none";
        case DebugView::Ids:
            return "ids: a false color per instance and triangle";
        case DebugView::Backfaces:
            return "backfaces: back-facing visible surfaces tinted red";
        case DebugView::Clipped:
            return "clipped: visible triangles that went through the clipper tinted cyan";
        case DebugView::ZFight:
            return "zfight: " + high +
                   " pixels (red) whose visible surface differs from a D32F reference";
        case DebugView::Mip:
            return "mip: texture level sampled " + low + " (blue) .. " + high +
                   " (yellow); grey untextured";
    }
    return "";
}

std::optional<DebugView> parse_debug_view(std::string_view name) {
    if (name == "lod") return DebugView::Mip;
    for (const NamedView& named : kNamedViews)
        if (named.name == name) return named.view;
    return std::nullopt;
}

}  // namespace zraster
