// Helpers of the 3D explain pictures: zraster's targets as images, projection of world points
// into the picture, colors, captions and frame selection.
#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/visibility.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "rgba_image.hpp"

namespace zraster::cli {

RgbaImage color_image(const RenderTargets& targets);
// Window depth as gray: near bright, far dark, empty (the clear value) black.
RgbaImage depth_image(const RenderTargets& targets, float clear_value);
RgbaImage side_by_side(const RgbaImage& left, const RgbaImage& right);
// The image with a band of text below it.
RgbaImage captioned(const RgbaImage& image, const std::string& text);
// Distinct colors for indices (golden-angle hues).
Rgba palette(std::size_t index);
// A polygon's vertices in the picture (window coordinates).
std::vector<glm::dvec2> window_points(const ScreenPolygon& polygon);
// A world point in a width x height picture seen by `camera`; nullopt behind the eye.
std::optional<glm::dvec2> project_point(const Camera& camera, int width, int height,
                                        const glm::dvec3& world);
// How many items go between frames: `step`, or about eight frames' worth.
std::size_t frame_step(std::size_t items, int step);
// The items counts after which frames are taken: step, 2 step, ..., items.
std::vector<std::size_t> frame_counts(std::size_t items, int step);

// A scene of the same instances whose triangles each get one of `colors` (a material each;
// class_of(instance, triangle) picks the color, -1 leaves the triangle out), flat shaded.
template <typename ClassOf>
Scene recolored_scene(const Scene& scene, const std::vector<glm::vec3>& colors, ClassOf class_of);

}  // namespace zraster::cli

#include "explain_scene_impl.hpp"
