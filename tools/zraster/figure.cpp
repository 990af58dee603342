// SVG and PNG output of a Figure.
#include "figure.hpp"

#include <fmt/format.h>

#include <cmath>

#include "bitmap_text.hpp"

namespace zraster::cli {
namespace {

std::string svg_color(Rgba c) {
    return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

std::string svg_paint(const char* name, Rgba c) {
    if (c.a == 0) return fmt::format(" {}=\"none\"", name);
    std::string s = fmt::format(" {}=\"{}\"", name, svg_color(c));
    if (c.a != 255) s += fmt::format(" {}-opacity=\"{:.3g}\"", name, c.a / 255.0);
    return s;
}

std::string svg_points(const std::vector<glm::dvec2>& points) {
    std::string s;
    for (const glm::dvec2& p : points)
        s += fmt::format("{}{:.6g},{:.6g}", s.empty() ? "" : " ", p.x, p.y);
    return s;
}

// Every other 6-pixel piece of the segment, for dashed lines in the PNG.
void draw_dashed(RgbaImage& image, glm::dvec2 a, glm::dvec2 b, Rgba color, int width) {
    const double length = glm::length(b - a);
    const int pieces = std::max(1, int(length / 6.0));
    for (int i = 0; i < pieces; i += 2)
        draw_line(image, a + (b - a) * (double(i) / pieces), a + (b - a) * (double(i + 1) / pieces),
                  color, width);
}

}  // namespace

std::string xml_escape(const std::string& text) {
    std::string s;
    for (const char c : text) {
        if (c == '<')
            s += "&lt;";
        else if (c == '>')
            s += "&gt;";
        else if (c == '&')
            s += "&amp;";
        else
            s += c;
    }
    return s;
}

Figure::Shape Figure::make_shape(Shape::Kind kind, std::vector<glm::dvec2> points,
                                 FigureStyle style) {
    Shape s;
    s.kind = kind;
    s.points = std::move(points);
    s.style = style;
    return s;
}

Figure::Figure(int width, int height, Rgba background)
    : width_(width), height_(height), background_(background) {}

void Figure::polygon(std::vector<glm::dvec2> points, FigureStyle style) {
    shapes_.push_back(make_shape(Shape::Kind::Polygon, std::move(points), style));
}

void Figure::polyline(std::vector<glm::dvec2> points, FigureStyle style) {
    shapes_.push_back(make_shape(Shape::Kind::Polyline, std::move(points), style));
}

void Figure::line(glm::dvec2 a, glm::dvec2 b, Rgba color, int width, bool dashed) {
    polyline({a, b}, FigureStyle{{0, 0, 0, 0}, color, width, dashed});
}

void Figure::rect(double x0, double y0, double x1, double y1, FigureStyle style) {
    polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, style);
}

void Figure::circle(glm::dvec2 center, double radius, Rgba fill) {
    Shape s = make_shape(Shape::Kind::Circle, {center}, FigureStyle{fill});
    s.radius = radius;
    shapes_.push_back(std::move(s));
}

void Figure::text(glm::dvec2 p, const std::string& text, Rgba color, int scale) {
    Shape s = make_shape(Shape::Kind::Text, {p}, FigureStyle{color});
    s.text = text;
    s.scale = scale;
    shapes_.push_back(std::move(s));
}

std::string Figure::svg() const {
    std::string s = fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\">\n<rect width=\"{0}\" "
        "height=\"{1}\"{2}/>\n",
        width_, height_, svg_paint("fill", background_));
    for (const Shape& shape : shapes_) {
        const FigureStyle& st = shape.style;
        const std::string dash = st.dashed ? " stroke-dasharray=\"6,6\"" : "";
        const std::string stroke = svg_paint("stroke", st.stroke) +
                                   fmt::format(" stroke-width=\"{}\"", st.stroke_width) + dash;
        switch (shape.kind) {
            case Shape::Kind::Polygon:
                s += fmt::format("<polygon points=\"{}\"{}{}/>\n", svg_points(shape.points),
                                 svg_paint("fill", st.fill), stroke);
                break;
            case Shape::Kind::Polyline:
                s += fmt::format("<polyline points=\"{}\" fill=\"none\"{}/>\n",
                                 svg_points(shape.points), stroke);
                break;
            case Shape::Kind::Circle:
                s += fmt::format("<circle cx=\"{:.6g}\" cy=\"{:.6g}\" r=\"{:.6g}\"{}/>\n",
                                 shape.points[0].x, shape.points[0].y, shape.radius,
                                 svg_paint("fill", st.fill));
                break;
            case Shape::Kind::Text: {
                // The bitmap font's lines are 12 pixels apart at scale 1; its cap height ~7.
                double y = shape.points[0].y + 8.0 * shape.scale;
                std::size_t start = 0;
                while (start <= shape.text.size()) {
                    const std::size_t end =
                        std::min(shape.text.find('\n', start), shape.text.size());
                    s += fmt::format(
                        "<text x=\"{:.6g}\" y=\"{:.6g}\" font-family=\"monospace\" "
                        "font-size=\"{}\"{}>{}</text>\n",
                        shape.points[0].x, y, 10 * shape.scale, svg_paint("fill", st.fill),
                        xml_escape(shape.text.substr(start, end - start)));
                    y += kTextLineHeight * shape.scale;
                    start = end + 1;
                }
                break;
            }
        }
    }
    return s + "</svg>\n";
}

RgbaImage Figure::raster() const {
    RgbaImage image(width_, height_, background_);
    for (const Shape& shape : shapes_) {
        const FigureStyle& st = shape.style;
        switch (shape.kind) {
            case Shape::Kind::Polygon:
            case Shape::Kind::Polyline: {
                const bool closed = shape.kind == Shape::Kind::Polygon;
                if (closed && st.fill.a) fill_polygon(image, shape.points, st.fill);
                if (!st.stroke.a) break;
                const std::size_t n = shape.points.size();
                for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
                    const glm::dvec2 a = shape.points[i], b = shape.points[(i + 1) % n];
                    if (st.dashed)
                        draw_dashed(image, a, b, st.stroke, st.stroke_width);
                    else
                        draw_line(image, a, b, st.stroke, st.stroke_width);
                }
                break;
            }
            case Shape::Kind::Circle: {
                std::vector<glm::dvec2> ring;
                for (int i = 0; i < 24; ++i) {
                    const double t = 2.0 * 3.141592653589793 * i / 24.0;
                    ring.push_back(shape.points[0] +
                                   shape.radius * glm::dvec2(std::cos(t), std::sin(t)));
                }
                fill_polygon(image, ring, st.fill);
                break;
            }
            case Shape::Kind::Text:
                draw_text(image, int(shape.points[0].x), int(shape.points[0].y), shape.text,
                          st.fill, shape.scale);
                break;
        }
    }
    return image;
}

}  // namespace zraster::cli
