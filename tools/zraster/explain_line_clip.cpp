// `zraster explain cohen-sutherland | liang-barsky | cyrus-beck`: built-in segments against a
// window, drawn with the clippers' own results.
#include <zraster/line_clip.hpp>

#include <fmt/format.h>

#include "explain_algorithms.hpp"

namespace zraster::cli {
namespace {

constexpr int kWidth = 520, kHeight = 380;
constexpr Rgba kAccepted{40, 170, 60, 255}, kRejected{210, 50, 40, 255},
    kClipped{240, 150, 20, 255}, kKept{30, 80, 220, 255}, kGray{130, 130, 130, 255};

// The picture's coordinates have y up (as the outcodes' "top" and "bottom" do).
glm::dvec2 screen(glm::dvec2 p) {
    return {p.x, kHeight - p.y};
}

const ClipRect kWindow{150, 110, 370, 270};

const std::vector<std::pair<glm::dvec2, glm::dvec2>>& example_segments() {
    static const std::vector<std::pair<glm::dvec2, glm::dvec2>> segments = {
        {{180, 150}, {330, 240}},  // inside
        {{40, 330}, {130, 360}},   // outside, above-left
        {{400, 60}, {500, 200}},   // outside, right
        {{60, 180}, {460, 220}},   // across
        {{200, 40}, {300, 350}},   // across, bottom to top
        {{90, 60}, {260, 200}},    // from a corner region into the window
        {{20, 240}, {200, 360}},   // corner to corner, missing the window
    };
    return segments;
}

std::string outcode_bits(std::uint32_t code) {
    // Top, bottom, right, left, as the textbooks write them.
    return fmt::format("{}{}{}{}", (code & kOutTop) ? 1 : 0, (code & kOutBottom) ? 1 : 0,
                       (code & kOutRight) ? 1 : 0, (code & kOutLeft) ? 1 : 0);
}

void draw_window(Figure& f, const std::vector<glm::dvec2>& corners) {
    std::vector<glm::dvec2> points;
    for (const glm::dvec2& c : corners) points.push_back(screen(c));
    f.polygon(points, FigureStyle{{230, 240, 255, 255}, {0, 0, 0, 255}, 2});
}

// Every boundary's parameter along a + t (b - a): entering (the inward normal faces the
// direction) or leaving. Skips boundaries parallel to the segment.
struct BoundaryParameter {
    double t;
    bool entering;
};
std::vector<BoundaryParameter> boundary_parameters(const ConvexWindow& w, glm::dvec2 a,
                                                   glm::dvec2 b) {
    std::vector<BoundaryParameter> out;
    const glm::dvec2 d = b - a;
    for (std::size_t i = 0; i < w.vertices.size(); ++i) {
        const double denominator = glm::dot(w.inward_normals[i], d);
        if (denominator == 0.0) continue;
        out.push_back(
            {-glm::dot(w.inward_normals[i], a - w.vertices[i]) / denominator, denominator > 0.0});
    }
    return out;
}

void parametric_figures(ExplainOutput& out, const std::string& name, const ConvexWindow& window,
                        bool rectangle) {
    Figure f(kWidth, kHeight + 30 + 26 * int(example_segments().size()));
    draw_window(f, window.vertices);
    for (std::size_t k = 0; k < example_segments().size(); ++k) {
        const auto [a, b] = example_segments()[k];
        const ClippedLine2 r =
            rectangle ? clip_line_liang_barsky(a, b, kWindow) : clip_line_cyrus_beck(a, b, window);
        f.line(screen(a), screen(b), kGray, 1, true);
        f.text(screen(a) + glm::dvec2(-12, -4), fmt::format("{}", k + 1));
        double t0 = 0.0, t1 = 1.0;
        for (const BoundaryParameter& p : boundary_parameters(window, a, b)) {
            if (p.t > 0.0 && p.t < 1.0)
                f.circle(screen(a + p.t * (b - a)), 3.5, p.entering ? kAccepted : kRejected);
            if (p.entering)
                t0 = std::max(t0, p.t);
            else
                t1 = std::min(t1, p.t);
        }
        if (r.visible) f.line(screen(r.a), screen(r.b), kKept, 3);
        // The number line: [0, 1], every boundary's t, the kept interval.
        const double y = kHeight + 30 + 26.0 * double(k), x0 = 60, x1 = 460;
        f.line({x0, y}, {x1, y}, kGray);
        f.text({10, y - 5}, fmt::format("{}", k + 1));
        for (const BoundaryParameter& p : boundary_parameters(window, a, b))
            if (p.t >= -0.2 && p.t <= 1.2)
                f.circle({x0 + (x1 - x0) * (p.t + 0.2) / 1.4, y}, 3,
                         p.entering ? kAccepted : kRejected);
        if (r.visible && t0 <= t1)
            f.line({x0 + (x1 - x0) * (t0 + 0.2) / 1.4, y}, {x0 + (x1 - x0) * (t1 + 0.2) / 1.4, y},
                   kKept, 3);
        f.text({x1 + 8, y - 5}, r.visible ? fmt::format("[{:.2f}, {:.2f}]", t0, t1) : "empty");
    }
    f.text({8, 8},
           "green: t where the segment enters a boundary; red: where it leaves; blue: the "
           "kept part [max entering t, min leaving t]");
    f.text({8, kHeight + 10}, "the parameter line of each segment, t from -0.2 to 1.2");
    out.figure(name, f,
               "each segment's boundary parameters, on it and on its parameter line, and the "
               "interval kept");
}

}  // namespace

void explain_cohen_sutherland(const ExplainInput&, ExplainOutput& out) {
    Figure f(kWidth, kHeight + 40);
    const ClipRect& w = kWindow;
    draw_window(f,
                {{w.x_min, w.y_min}, {w.x_max, w.y_min}, {w.x_max, w.y_max}, {w.x_min, w.y_max}});
    for (const double x : {w.x_min, w.x_max})
        f.line(screen({x, 0}), screen({x, kHeight}), kGray, 1, true);
    for (const double y : {w.y_min, w.y_max})
        f.line(screen({0, y}), screen({kWidth, y}), kGray, 1, true);
    for (const double x : {75.0, 260.0, 445.0})
        for (const double y : {55.0, 190.0, 325.0})
            f.text(screen({x - 12, y + 4}), outcode_bits(outcode({x, y}, w)), {150, 150, 150, 255});
    int accepted = 0, rejected = 0, clipped = 0;
    for (const auto& [a, b] : example_segments()) {
        LineClipStats stats;
        const ClippedLine2 r = clip_line_cohen_sutherland(a, b, w, &stats);
        if (stats.trivial_accepts) {
            f.line(screen(a), screen(b), kAccepted, 3);
            ++accepted;
        } else if (stats.trivial_rejects) {
            f.line(screen(a), screen(b), kRejected, 2);
            ++rejected;
        } else {
            f.line(screen(a), screen(b), kClipped, 2, true);
            if (r.visible) f.line(screen(r.a), screen(r.b), kClipped, 4);
            ++clipped;
        }
        for (const glm::dvec2 p : {a, b}) {
            f.circle(screen(p), 3, {0, 0, 0, 255});
            f.text(screen(p) + glm::dvec2(5, -4), outcode_bits(outcode(p, w)));
        }
    }
    f.text({8, 8}, fmt::format("outcodes TBRL; green: trivially accepted ({}), red: trivially "
                               "rejected ({}), orange: clipped ({}), kept part thick",
                               accepted, rejected, clipped));
    out.figure("cohen-sutherland", f,
               "the nine regions with their outcodes, and segments trivially accepted, "
               "trivially rejected or clipped");
}

void explain_liang_barsky(const ExplainInput&, ExplainOutput& out) {
    parametric_figures(out, "liang-barsky", make_convex_window(kWindow), true);
}

void explain_cyrus_beck(const ExplainInput&, ExplainOutput& out) {
    const std::vector<glm::dvec2> hexagon = {{170, 120}, {320, 100}, {400, 190},
                                             {340, 280}, {190, 290}, {120, 200}};
    parametric_figures(out, "cyrus-beck", make_convex_window(hexagon), false);
}

}  // namespace zraster::cli
