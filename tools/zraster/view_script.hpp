// Input scripts for `zraster view --script FILE`: events to replay at given frames, for tests and
// recorded demos. The format (docs/viewer.md):
//
//   # comment; blank lines are ignored
//   FRAME key K              K: one character as typed (1, v, a, ...) or esc
//   FRAME drag BUTTON DX DY  BUTTON: left (orbit), right or middle (pan); pixels, y down
//   FRAME wheel N            notches, positive zooms in
//   FRAME resize W H         the window's new size
//   FRAME quit
//
// An event with FRAME f is applied once f frames have been shown (0: before the first); events
// of one frame apply in file order (resizes in a row within one frame: the last). Frames must not
// decrease.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "view_state.hpp"

namespace zraster::cli {

struct ScriptEvent {
    long long frame = 0;
    InputEvent event;
};

// Throws InputError naming the file and the line for anything malformed.
std::vector<ScriptEvent> read_view_script(const std::filesystem::path& path);
std::vector<ScriptEvent> parse_view_script(const std::string& text, const std::string& name);

}  // namespace zraster::cli
