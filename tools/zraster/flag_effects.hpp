// Flags that would change nothing in the frame the others ask for (a depth test setting for an
// algorithm without that depth buffer, an edge color without edges, lights with unlit shading,
// a texture filter without textures): refused by name before any work, so that nobody trusts a
// setting that was never applied. The frame code itself takes such settings in any combination
// (the viewer switches algorithms under them); this is the command line's and Python's check.
#pragma once
#include <string>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::cli {

// Throws InputError naming the first flag of `a` without effect. Returns warnings (without
// "warning: ") for settings that apply but make the image the background whatever the scene: a
// depth compare that nothing passes against the cleared depth buffer.
std::vector<std::string> check_flags_take_effect(const RenderArguments& a);

// Warnings (without "warning: ") for flags that change nothing in this scene, which a service
// may pass to every file: --texture-filter when no instance is textured, --alpha-mode opaque when
// every instance is opaque already, --interpolation linear with flat shading when nothing is
// interpolated (no texture, no vertex colors, no `normal_output`).
std::vector<std::string> scene_flag_warnings(const RenderArguments& a, const Scene& scene,
                                             bool normal_output);

// The same for `zraster svg`, which draws no depth buffer and strokes outlines only with its
// --edges (`edges`); `edge_width_given`: --edge-width was given.
void check_svg_flags_take_effect(const RenderArguments& a, bool edges, bool edge_width_given);

}  // namespace zraster::cli
