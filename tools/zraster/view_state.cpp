// The viewer's state and how input changes it.
#include "view_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "camera_ranges.hpp"
#include "command_line.hpp"

namespace zraster::cli {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
// Straight above or below, the orbit's up vector flips; stop just short of it.
constexpr double kMaxElevation = 89.0;

constexpr std::array<const char*, 5> kAlgorithms = {"zbuffer", "painter", "bsp", "warnock",
                                                    "abuffer"};

// The orbit that `camera` is: around its target, distance in radii.
OrbitCamera orbit_of(const RenderArguments& a, const Camera& camera, const BoundingSphere& sphere,
                     double radius) {
    OrbitCamera orbit;
    if (!a.orbit.empty()) {
        const glm::dvec3 o = parse_vec3("--orbit", a.orbit);
        orbit.azimuth = o.x;
        orbit.elevation = o.y;
        orbit.distance = o.z;
        return orbit;
    }
    const glm::dvec3 offset = camera.eye - camera.target;
    const double length = glm::length(offset);
    if (length > 0.0) {
        orbit.azimuth = std::atan2(offset.x, offset.z) * kDegrees;
        orbit.elevation = std::asin(std::clamp(offset.y / length, -1.0, 1.0)) * kDegrees;
        orbit.distance = length / radius;
    }
    orbit.pan = camera.target - sphere.center;
    return orbit;
}

}  // namespace

ViewState::ViewState(const RenderArguments& initial, std::span<const glm::vec3> world)
    : initial_(initial), args_(initial), sphere_(bounding_sphere(world)) {
    if (!(sphere_.radius > 0.0)) sphere_.radius = 1.0;  // as place_camera frames a point
    const RenderOptions options = make_render_options(initial, world, std::nullopt);
    start_camera_ = orbit_of(initial, *options.camera, sphere_, sphere_.radius);
    camera_ = start_camera_;
    antialias_ = initial.aa > 1;
    // --view starts the d key's cycle there (the requests carry the view, not the flag).
    view_ = options.view;
    args_.view = "none";
}

void ViewState::apply(const InputEvent& event) {
    switch (event.kind) {
        case InputEvent::Kind::Key:
            apply_key(event.key);
            return;
        case InputEvent::Kind::Drag:
            if (event.button == MouseButton::Left)
                orbit(event.dx, event.dy);
            else
                pan(event.dx, event.dy);
            break;
        case InputEvent::Kind::Wheel:
            // Kept within --orbit's distance range however far the wheel turns (the frame's
            // camera is checked against it): 1e-6 radii is well inside the scene.
            camera_.distance = std::clamp(camera_.distance * std::pow(kZoomPerNotch, event.wheel),
                                          1e-6, kMaxOrbitDistance);
            camera_.moved = true;
            break;
        case InputEvent::Kind::Resize: {
            const std::string size =
                fmt::format("{}x{}", std::max(event.width, 1), std::max(event.height, 1));
            if (size == args_.size) return;
            args_.size = size;
            break;
        }
        case InputEvent::Kind::Quit:
            quit_ = true;
            return;
    }
    ++serial_;
}

void ViewState::apply_key(char key) {
    switch (key) {
        case '1':
            args_.shading = "flat";
            break;
        case '2':
            args_.shading = "gouraud";
            break;
        case '3':
            args_.shading = "phong";
            break;
        case 'v': {
            const auto* current =
                std::find(kAlgorithms.begin(), kAlgorithms.end(), args_.visibility);
            const std::size_t index =
                current == kAlgorithms.end() ? 0 : std::size_t(current - kAlgorithms.begin());
            args_.visibility = kAlgorithms[(index + 1) % kAlgorithms.size()];
            break;
        }
        case 'a':
            antialias_ = !antialias_;
            break;
        case 'w':
            // none -> wireframe -> hidden-line -> none
            if (args_.wireframe) {
                args_.wireframe = false;
                args_.hidden_line = true;
            } else if (args_.hidden_line) {
                args_.hidden_line = false;
            } else {
                args_.wireframe = true;
            }
            break;
        case 'c': {
            const bool culling = !args_.no_cull && args_.cull != "none";
            const bool initially_none = initial_.no_cull || initial_.cull == "none";
            args_.no_cull = false;
            args_.cull = culling ? "none" : (initially_none ? "back" : initial_.cull);
            break;
        }
        case 'o':
            args_.occlusion_cull = !args_.occlusion_cull;
            break;
        case 'z':
            // d32f -> d24 -> d16 -> reversed-Z (d32f) -> d32f
            if (args_.reversed_z) {
                args_.reversed_z = false;
                args_.depth_format = "d32f";
            } else if (args_.depth_format == "d32f") {
                args_.depth_format = "d24";
            } else if (args_.depth_format == "d24") {
                args_.depth_format = "d16";
            } else {
                args_.depth_format = "d32f";
                args_.reversed_z = true;
            }
            break;
        case 'd': {
            const std::span<const DebugView> views = debug_views();
            const auto current = std::find(views.begin(), views.end(), view_);
            const std::size_t index =
                current == views.end() ? 0 : std::size_t(current - views.begin());
            view_ = views[(index + 1) % views.size()];
            break;
        }
        case 'r': {
            const std::string size = args_.size;
            args_ = initial_;
            args_.size = size;
            args_.view = "none";
            camera_ = start_camera_;
            view_ = DebugView::None;
            antialias_ = initial_.aa > 1;
            break;
        }
        case 's':
            ++screenshots_;
            return;
        case 'h':
            help_ = !help_;
            return;
        case 'q':
        case kEscapeKey:
            quit_ = true;
            return;
        default:
            return;  // other keys do nothing
    }
    ++serial_;
}

void ViewState::orbit(double dx, double dy) {
    // Dragging right turns the scene right: the eye goes left around it.
    // Within [-180, 180] (an exact remainder): any number of drags stays in --orbit's range.
    camera_.azimuth = std::remainder(camera_.azimuth - dx * kDegreesPerPixel, 360.0);
    camera_.elevation =
        std::clamp(camera_.elevation + dy * kDegreesPerPixel, -kMaxElevation, kMaxElevation);
    camera_.moved = true;
}

void ViewState::pan(double dx, double dy) {
    // The target follows the pointer: one pixel moves it by the view's height at the target
    // divided by the window's height.
    const glm::ivec2 size = parse_size("--size", args_.size, kMaxViewport);
    const double fovy = (initial_.fovy ? *initial_.fovy : 60.0) / kDegrees;
    const double view_height = 2.0 * camera_.distance * sphere_.radius * std::tan(fovy / 2.0);
    const double per_pixel = view_height / double(size.y);
    const glm::dvec3 forward = -eye_direction();
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    camera_.pan += (-dx * right + dy * up) * per_pixel;
    camera_.moved = true;
}

glm::dvec3 ViewState::eye_direction() const {
    const double az = camera_.azimuth / kDegrees, el = camera_.elevation / kDegrees;
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

RenderArguments ViewState::render_arguments() const {
    RenderArguments a = args_;
    if (camera_.moved) {
        a.orbit.clear();
        a.eye.clear();
        a.target.clear();
        const auto triple = [](const glm::dvec3& v) {
            return exact_number(v.x) + "," + exact_number(v.y) + "," + exact_number(v.z);
        };
        if (camera_.pan == glm::dvec3(0.0)) {
            a.orbit = triple({camera_.azimuth, camera_.elevation, camera_.distance});
        } else {
            const glm::dvec3 target = sphere_.center + camera_.pan;
            a.target = triple(target);
            a.eye = triple(target + eye_direction() * (camera_.distance * sphere_.radius));
        }
    }
    const bool edges = a.wireframe || a.hidden_line;
    if (a.visibility != "zbuffer") {
        a.wireframe = a.hidden_line = false;
        a.msaa = false;
        if (a.visibility != "abuffer" || !antialias_) a.aa = 1;
    } else if (!antialias_ || edges) {
        a.aa = 1;
        a.msaa = false;
    } else if (a.aa == 1) {
        a.aa = 4;  // the a key's antialiasing: 4x4 multisampling
        a.msaa = true;
    }
    return a;
}

std::string ViewState::note() const {
    const bool edges = args_.wireframe || args_.hidden_line;
    if (edges && args_.visibility != "zbuffer") return "edges need the z-buffer";
    if (antialias_ && edges) return "no antialiasing with edges";
    if (antialias_ && args_.visibility != "zbuffer" && args_.visibility != "abuffer")
        return "no antialiasing here";
    return "";
}

std::string ViewState::camera_flags() const {
    const RenderArguments a = render_arguments();
    if (!a.orbit.empty()) return "--orbit " + a.orbit;
    std::string flags;
    if (!a.eye.empty()) flags += "--eye " + a.eye;
    if (!a.target.empty()) flags += (flags.empty() ? "" : " ") + ("--target " + a.target);
    return flags.empty() ? "(the default camera)" : flags;
}

std::string ViewState::algorithm_name() const {
    const RenderArguments a = render_arguments();
    if (a.visibility == "painter") return "painter's";
    if (a.visibility == "bsp") return "BSP";
    if (a.visibility == "warnock") return "Warnock";
    if (a.visibility == "abuffer") {
        const int n = a.aa == 1 ? 4 : a.aa;
        return fmt::format("A-buffer {}x{}", n, n);
    }
    if (a.aa > 1) return fmt::format("z-buffer {} {}x{}", a.msaa ? "MSAA" : "SSAA", a.aa, a.aa);
    return "z-buffer";
}

}  // namespace zraster::cli
