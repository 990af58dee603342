// What `zraster view` shows: the render flags, the orbiting camera and the viewer's own toggles,
// changed by input events (keys, drags, the wheel, resizes) from the window or a script. Pure
// logic, no window: the frames it describes are those of `zraster render` with the flags that
// render_arguments() returns, so a screenshot can be checked against the command.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/debug_view.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>

#include "render_arguments.hpp"

namespace zraster::cli {

enum class MouseButton { Left, Right, Middle };

// One input, as the window or a script (view_script.hpp) delivers it.
struct InputEvent {
    enum class Kind { Key, Drag, Wheel, Resize, Quit };
    Kind kind = Kind::Key;
    char key = 0;  // Kind::Key: '1', 'v', ... as typed; kEscapeKey for Esc
    MouseButton button = MouseButton::Left;
    double dx = 0.0, dy = 0.0;  // Kind::Drag: pointer motion in pixels, y down
    double wheel = 0.0;         // Kind::Wheel: notches, positive away from the user (zoom in)
    int width = 0, height = 0;  // Kind::Resize: the window's new size in pixels
};
inline constexpr char kEscapeKey = 27;

// The camera as the viewer moves it: an orbit around a target point, distances in radii of the
// scene's bounding sphere (as --orbit measures them). Until the first move it is the command's
// default camera exactly.
struct OrbitCamera {
    double azimuth = 0.0, elevation = 0.0;  // degrees, as --orbit
    double distance = 3.0;                  // bounding-sphere radii
    glm::dvec3 pan{0.0};                    // target minus the sphere's center, world units
    bool moved = false;
};

// Degrees of orbit per pixel dragged, and the distance factor per wheel notch: both exact in
// binary, so that a scripted move lands on round --orbit values.
inline constexpr double kDegreesPerPixel = 0.25;
inline constexpr double kZoomPerNotch = 0.875;

class ViewState {
  public:
    // `initial`: the command line's flags (--size is the window's first size). `world`: the
    // scene's world-space vertices, for the default framing and the bounding sphere.
    ViewState(const RenderArguments& initial, std::span<const glm::vec3> world);

    void apply(const InputEvent& event);

    // The flags of the frame to draw now: the toggles made consistent (a combination render
    // would refuse is dropped, and note() says so), the camera as --orbit or --eye/--target.
    RenderArguments render_arguments() const;
    DebugView debug_view() const { return view_; }
    // Changes with every input that changes the frame (not with help or screenshots).
    std::uint64_t serial() const { return serial_; }

    bool quit() const { return quit_; }
    bool help() const { return help_; }
    // Screenshots asked for with the s key, counted.
    int screenshots_requested() const { return screenshots_; }
    // Why a toggle has no effect in the current combination ("" when all apply).
    std::string note() const;
    // The camera flags that reproduce the current view with `zraster render`.
    std::string camera_flags() const;
    // The algorithm, as the HUD names it ("z-buffer", "painter's", ...).
    std::string algorithm_name() const;

  private:
    void apply_key(char key);
    void orbit(double dx, double dy);
    void pan(double dx, double dy);
    glm::dvec3 eye_direction() const;

    RenderArguments initial_, args_;
    BoundingSphere sphere_;
    OrbitCamera start_camera_, camera_;
    DebugView view_ = DebugView::None;
    bool antialias_ = false;
    bool quit_ = false, help_ = false;
    int screenshots_ = 0;
    std::uint64_t serial_ = 0;
};

}  // namespace zraster::cli
