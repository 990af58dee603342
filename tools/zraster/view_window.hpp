// The viewer's window (tools/viewer/sdl_window.cpp with SDL2; tools/viewer/no_window.cpp, which
// refuses, in a build without it).
#pragma once
#include <zraster/scene.hpp>

#include <glm/glm.hpp>

#include <span>
#include <string>
#include <vector>

#include "view_script.hpp"
#include "view_state.hpp"

namespace zraster::cli {

struct ViewSetup {
    const Scene& scene;
    std::span<const glm::vec3> world;  // the scene's world-space vertices
    ViewState& state;
    std::vector<ScriptEvent> script;
    long long frames = 0;    // exit after this many frames shown (0: when the user quits)
    std::string screenshot;  // the last frame as shown, to this PNG at exit ("": none)
    bool hud = true;
    std::string title;
};

struct ViewSummary {
    long long frames_shown = 0;
    double seconds = 0.0;           // from the first request to the exit
    std::vector<double> render_ms;  // of every frame drawn
};

// Opens the window and runs until the user quits (or the frames or the script end). Throws
// InputError("view", ...) with a one-line cause when no window can be opened (no display).
ViewSummary run_view_window(ViewSetup& setup);

}  // namespace zraster::cli
