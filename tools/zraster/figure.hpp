// A small vector figure for the explain pictures: shapes in pixel coordinates (y down), written
// as SVG and rasterized to PNG by the same description, so the two always show the same thing.
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "rgba_image.hpp"

namespace zraster::cli {

// Text with <, > and & escaped, for SVG and HTML.
std::string xml_escape(const std::string& text);

struct FigureStyle {
    Rgba fill{0, 0, 0, 0};  // alpha 0: not filled
    Rgba stroke{0, 0, 0, 0};
    int stroke_width = 1;
    bool dashed = false;
};

class Figure {
  public:
    Figure(int width, int height, Rgba background = {255, 255, 255, 255});

    void polygon(std::vector<glm::dvec2> points, FigureStyle style);
    void polyline(std::vector<glm::dvec2> points, FigureStyle style);
    void line(glm::dvec2 a, glm::dvec2 b, Rgba color, int width = 1, bool dashed = false);
    void rect(double x0, double y0, double x1, double y1, FigureStyle style);
    void circle(glm::dvec2 center, double radius, Rgba fill);
    // Text with its top-left corner at p, in the bitmap font's size (scale 1 or 2).
    void text(glm::dvec2 p, const std::string& text, Rgba color = {0, 0, 0, 255}, int scale = 1);

    int width() const { return width_; }
    int height() const { return height_; }
    std::string svg() const;
    RgbaImage raster() const;

  private:
    struct Shape {
        enum class Kind { Polygon, Polyline, Circle, Text } kind = Kind::Polygon;
        std::vector<glm::dvec2> points;
        FigureStyle style;
        double radius = 0.0;
        std::string text;
        int scale = 1;
    };
    static Shape make_shape(Shape::Kind kind, std::vector<glm::dvec2> points, FigureStyle style);
    int width_, height_;
    Rgba background_;
    std::vector<Shape> shapes_;
};

}  // namespace zraster::cli
