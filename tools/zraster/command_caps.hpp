// Caps a caller of run_zraster() in the same process may put on the work one run may ask for,
// below the command's documented limits: the fuzzer (fuzz/fuzz_cli.cpp) sets them small, so that
// large --size, --aa, --threads, --frames, --warmup, --jobs and procedural scene sizes are
// checked (refused or clamped) by the command itself, as it checks them against its ordinary
// limits, and every run stays fast. The command never sets them: 0 means no cap.
#pragma once
#include <cstdint>
#include <string>

namespace zraster::cli {

struct CommandCaps {
    std::uint64_t max_samples = 0;          // width x height x aa^2 of an image
    std::uint64_t max_scene_triangles = 0;  // a procedural scene's triangles, estimated
    int max_frames = 0;                     // bench: --frames + --warmup
    int max_threads = 0;                    // --threads, batch --jobs (clamped, with a warning)
};

void set_command_caps(const CommandCaps& caps);
const CommandCaps& command_caps();

// Throws InputError(option, ...) when a WIDTHxHEIGHT image of aa x aa samples a pixel is past
// the cap.
void check_samples_cap(const std::string& option, int width, int height, int aa);
// Throws InputError(spec, ...) for a procedural spec (sphere:N, city:N, soup:N, building:RxC)
// whose scene would be past the cap; does nothing for other specs.
void check_scene_cap(const std::string& spec);
// `threads` (or --jobs), clamped to the cap with a warning on stderr.
int capped_threads(const std::string& option, int threads);

}  // namespace zraster::cli
