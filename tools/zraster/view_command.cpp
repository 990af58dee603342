// `zraster view`: the command's flags, checks and summary around the window.
#include "view_command.hpp"

#include <zraster/error.hpp>
#include <zraster/output_files.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "command_line.hpp"
#include "flag_effects.hpp"
#include "output_maps.hpp"
#include "run_inputs.hpp"
#include "view_script.hpp"
#include "view_state.hpp"
#include "view_window.hpp"

namespace zraster::cli {
namespace {

// The median of the frames' render times (0 when none).
double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2),
                     values.end());
    return values[values.size() / 2];
}

// --screenshot is checked before any work as every output is (OutputFiles); the window writes
// it at exit through write_png8, the same mechanism. Checked again once the model is loaded, with
// the files it named.
void check_screenshot_path(const ViewArguments& a,
                           const std::vector<std::filesystem::path>& files_read = {}) {
    OutputFiles outputs;
    check_output(outputs, a.screenshot, {".png"}, "--screenshot");
    check_run_inputs(a.render, outputs);
    outputs.check_input(a.script, "--script");
    for (const std::filesystem::path& file : files_read)
        outputs.check_input(file, file_named_by(a.render.scene));
}

}  // namespace

void add_view_command(CLI::App& app, ViewArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "view", "Show a scene in a window: orbit, zoom and switch algorithms (docs/viewer.md)");
    a.render.size = "1280x720";
    add_render_arguments(*cmd, a.render);
    add_frame_arguments(*cmd, a.render);
    cmd->add_option("--frames", a.frames, "Exit after this many frames have been shown (0: never)")
        ->check(CLI::Range(0LL, 1'000'000'000LL))
        ->capture_default_str();
    cmd->add_option("--screenshot", a.screenshot, "At exit, write the last frame as shown (PNG)");
    cmd->add_option("--script", a.script,
                    "Replay input events from this file (format in docs/viewer.md)");
    cmd->add_flag("--no-hud", a.no_hud, "Hide the line of timings and settings");
}

int run_view(const ViewArguments& a) {
    check_frame_arguments(a.render);
    for (const std::string& w : check_flags_take_effect(a.render))
        fmt::print(stderr, "warning: {}\n", w);
    check_screenshot_path(a);
    std::vector<ScriptEvent> script;
    if (!a.script.empty()) script = read_view_script(a.script);
    // A window resized by the script is a frame of that size: within --max-pixels, as --size is.
    for (const ScriptEvent& e : script)
        if (e.event.kind == InputEvent::Kind::Resize &&
            std::uint64_t(e.event.width) * std::uint64_t(e.event.height) > a.render.max_pixels)
            throw InputError(a.script, "a resize to " + std::to_string(e.event.width) + "x" +
                                           std::to_string(e.event.height) + " at frame " +
                                           std::to_string(e.frame) +
                                           " is more pixels than --max-pixels " +
                                           std::to_string(a.render.max_pixels));
    std::vector<std::filesystem::path> files_read;
    const Scene scene = load_scene_or_procedural(a.render.scene, nullptr, nullptr, &files_read);
    check_screenshot_path(a, files_read);
    check_instanced_vertices(scene,
                             parse_byte_size("--max-frame-bytes", a.render.max_frame_bytes_text));
    const std::vector<glm::vec3> world = scene.world_positions();
    std::optional<ViewState> state;
    try {
        state.emplace(a.render, world);
    } catch (const InputError& e) {
        if (!e.file().empty()) throw;
        throw InputError(scene.name, e.cause());  // (the camera fit: about the scene)
    }
    ViewSetup setup{scene,    world,        *state,    std::move(script),
                    a.frames, a.screenshot, !a.no_hud, "zraster view " + a.render.scene};
    const ViewSummary summary = run_view_window(setup);
    const double fps = summary.seconds > 0.0 ? double(summary.frames_shown) / summary.seconds : 0.0;
    fmt::print("view: {} frames in {:.2f} s ({:.1f} fps), render median {:.2f} ms\n",
               summary.frames_shown, summary.seconds, fps, median(summary.render_ms));
    fmt::print("view: camera {}\n", state->camera_flags());
    return kExitOk;
}

}  // namespace zraster::cli
