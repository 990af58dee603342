#include <zraster/debug_view.hpp>

#include <array>
#include <cstddef>

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

}  // namespace

std::span<const DebugView> debug_views() {
    return kViews;
}

std::string_view debug_view_name(DebugView view) {
    for (const NamedView& named : kNamedViews)
        if (named.view == view) return named.name;
    return "none";
}

std::optional<DebugView> parse_debug_view(std::string_view name) {
    if (name == "lod") return DebugView::Mip;
    for (const NamedView& named : kNamedViews)
        if (named.name == name) return named.view;
    return std::nullopt;
}

}  // namespace zraster
