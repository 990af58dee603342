// `zraster explain frustum-culling | backface-culling | occlusion-culling`: what each removes,
// colored, seen from the camera and from a second camera beside it.
#include <zraster/camera.hpp>
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <set>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

const glm::vec3 kKeptColor{0.25f, 0.75f, 0.3f}, kRemovedColor{0.85f, 0.2f, 0.15f},
    kClippedColor{0.95f, 0.6f, 0.1f}, kOutsideColor{0.55f, 0.55f, 0.55f};

// A camera up and to the side of `camera`, twice as far from its target: the view that shows
// what the camera does not.
Camera side_camera(const Camera& camera) {
    const glm::dvec3 offset = camera.eye - camera.target;
    const double distance = glm::length(offset);
    const double azimuth = glm::degrees(std::atan2(offset.x, offset.z)) + 70.0;
    Camera side = orbit_camera(camera.target, 2.2 * distance, azimuth, 30.0, 50.0);
    side.near = 0.02 * distance;
    side.far = 6.0 * distance;
    return side;
}

RgbaImage draw_from(const Scene& scene, const RenderOptions& options, const Camera& camera,
                    CullMode cull) {
    RenderOptions o = options;
    o.camera = camera;
    o.cull = cull;
    o.occlusion_cull = false;
    o.shading = ShadingMode::Flat;
    return color_image(render(scene, o).targets);
}

// The eye and the view volume's edges drawn into a picture taken by `viewer`.
void draw_frustum(RgbaImage& image, const Camera& viewer, const Camera& camera, double aspect) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(camera.view_projection(aspect)));
    std::vector<std::optional<glm::dvec2>> corners;
    for (const double z : {-1.0, 1.0})
        for (const auto& [x, y] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
            const glm::dvec4 p = inverse * glm::dvec4(x, y, z, 1.0);
            corners.push_back(
                project_point(viewer, image.width, image.height, glm::dvec3(p) / p.w));
        }
    const Rgba color{255, 255, 255, 255};
    const auto edge = [&](int i, int j) {
        if (corners[std::size_t(i)] && corners[std::size_t(j)])
            draw_line(image, *corners[std::size_t(i)], *corners[std::size_t(j)], color);
    };
    for (int i = 0; i < 4; ++i) {
        edge(i, (i + 1) % 4);
        edge(4 + i, 4 + (i + 1) % 4);
        edge(i, 4 + i);
    }
    if (const auto eye = project_point(viewer, image.width, image.height, camera.position()))
        fill_rect(image, int(eye->x) - 3, int(eye->y) - 3, int(eye->x) + 4, int(eye->y) + 4,
                  Rgba{255, 230, 0, 255});
}

// The outcodes (six planes of the view volume) of a triangle's three vertices.
std::array<std::uint32_t, 3> triangle_outcodes(const glm::mat4& mvp, const Mesh& mesh,
                                               std::size_t t) {
    std::array<std::uint32_t, 3> codes{};
    for (int k = 0; k < 3; ++k) {
        const glm::vec4 c =
            mvp * glm::vec4(mesh.positions[mesh.indices[3 * t + std::size_t(k)]], 1.0f);
        codes[std::size_t(k)] = (c.x < -c.w ? 1u : 0u) | (c.x > c.w ? 2u : 0u) |
                                (c.y < -c.w ? 4u : 0u) | (c.y > c.w ? 8u : 0u) |
                                (c.z < -c.w ? 16u : 0u) | (c.z > c.w ? 32u : 0u);
    }
    return codes;
}

void two_views(ExplainOutput& out, const std::string& name, const Scene& colored,
               const RenderOptions& options, const Camera& camera, CullMode camera_cull,
               const std::string& legend, const std::string& caption) {
    const std::string stage = "explain " + name + ": drawing the two views";
    if (options.progress != nullptr) options.progress->report(stage.c_str(), 0.0);
    RgbaImage from_camera = draw_from(colored, options, camera, camera_cull);
    if (options.progress != nullptr) options.progress->report(stage.c_str(), 0.5);
    const Camera side = side_camera(camera);
    RgbaImage from_side = draw_from(colored, options, side, CullMode::None);
    draw_frustum(from_side, side, camera, double(options.width) / double(options.height));
    out.still(name,
              captioned(side_by_side(from_camera, from_side),
                        "left: from the camera; right: from beside it (yellow: the eye, "
                        "white: the view volume)\n" +
                            legend),
              caption);
}

// The one picture of each culling: the camera's view and the side view, side by side.
void check_two_views(const ExplainInput& in, const std::string& algorithm) {
    check_explain_pixels(
        1, (2 * std::uint64_t(in.options.width) + 4) * std::uint64_t(in.options.height),
        in.max_pixels, "explain " + algorithm + "'s two views");
}

}  // namespace

void explain_frustum_culling(const ExplainInput& in, ExplainOutput& out) {
    check_two_views(in, "frustum-culling");
    // The command's camera with half its field of view, so that part of the scene is outside.
    Camera camera = effective_camera(in.scene, in.options);
    camera.fovy_degrees *= 0.5;
    const double aspect = double(in.options.width) / double(in.options.height);
    const glm::mat4 view_projection = camera.view_projection(aspect);
    std::size_t counts[3] = {};
    const Scene colored = recolored_scene(
        in.scene, {kKeptColor, kClippedColor, kRemovedColor}, [&](std::size_t i, std::size_t t) {
            const Instance& instance = in.scene.instances[i];
            const auto codes = triangle_outcodes(view_projection * instance.transform,
                                                 in.scene.meshes[instance.mesh], t);
            const int c = (codes[0] & codes[1] & codes[2])   ? 2
                          : (codes[0] | codes[1] | codes[2]) ? 1
                                                             : 0;
            ++counts[c];
            return c;
        });
    two_views(out, "frustum-culling", colored, in.options, camera, in.options.cull,
              fmt::format("green: inside ({}), orange: crossing a plane, clipped ({}), red: "
                          "outside one plane, rejected ({})",
                          counts[0], counts[1], counts[2]),
              "the triangles inside, clipped and rejected by the view volume of the camera "
              "(its field of view halved so that part of the scene is outside)");
}

void explain_backface_culling(const ExplainInput& in, ExplainOutput& out) {
    check_two_views(in, "backface-culling");
    RenderOptions all = in.options;
    all.cull = CullMode::None;
    std::set<std::pair<std::int32_t, std::int32_t>> front, back;
    for (const ScreenPolygon& p : project_scene(in.scene, all))
        (p.front_facing ? front : back).insert({p.instance, p.primitive});
    std::size_t counts[3] = {};
    const Scene colored = recolored_scene(
        in.scene, {kKeptColor, kRemovedColor, kOutsideColor}, [&](std::size_t i, std::size_t t) {
            const std::pair key{std::int32_t(i), std::int32_t(t)};
            const int c = front.count(key) ? 0 : back.count(key) ? 1 : 2;
            ++counts[c];
            return c;
        });
    two_views(out, "backface-culling", colored, in.options, effective_camera(in.scene, in.options),
              CullMode::None,
              fmt::format("green: facing the camera ({}), red: facing away, culled ({}), gray: "
                          "outside the view or too small ({})",
                          counts[0], counts[1], counts[2]),
              "the triangles back-face culling removes (red), seen from the camera and from "
              "beside it");
}

// Instances as the renderer's frame left them: visible (a pixel in the image), drawn but hidden
// (the conservative test could not prove them hidden), skipped by occlusion culling, and outside
// the view (or skipped by another culling).
void explain_occlusion_culling(const ExplainInput& in, ExplainOutput& out) {
    check_two_views(in, "occlusion-culling");
    RenderOptions options = in.options;
    options.id_targets = true;
    options.occlusion_cull = true;
    options.report_instance_outcomes = true;
    enum Class { kVisible, kHiddenDrawn, kOcclusionCulled, kOutside };
    std::vector<int> class_of_instance(in.scene.instances.size(), kOutside);
    std::size_t counts[4] = {};
    in.report("explain occlusion-culling: drawing the culled frame", 0.0);
    {  // (the frame's targets go before the two views are drawn)
        const RenderResult frame = render(in.scene, options);
        const std::set<std::int32_t> visible(frame.targets.instance_id.begin(),
                                             frame.targets.instance_id.end());
        for (std::size_t i = 0; i < in.scene.instances.size(); ++i) {
            const InstanceOutcome outcome = frame.instance_outcomes.at(i);
            int c = kOutside;
            if (visible.count(std::int32_t(i)))
                c = kVisible;
            else if (outcome == InstanceOutcome::Drawn)
                c = kHiddenDrawn;
            else if (outcome == InstanceOutcome::OcclusionCulled)
                c = kOcclusionCulled;
            class_of_instance[i] = c;
            ++counts[c];
        }
    }
    const Scene colored =
        recolored_scene(in.scene, {kKeptColor, kClippedColor, kRemovedColor, kOutsideColor},
                        [&](std::size_t i, std::size_t) { return class_of_instance[i]; });
    two_views(out, "occlusion-culling", colored, in.options, effective_camera(in.scene, in.options),
              in.options.cull,
              fmt::format("instances: green visible ({}), orange hidden but drawn ({}), red "
                          "skipped by occlusion culling ({}),\ngray outside the view ({})",
                          counts[kVisible], counts[kHiddenDrawn], counts[kOcclusionCulled],
                          counts[kOutside]),
              "what occlusion culling removed (red): instances hidden behind the occluders, never "
              "sent through the vertex stage; orange ones are hidden too, but the conservative "
              "test kept them");
}

}  // namespace zraster::cli
