// The renderer's checks of what the caller passes (scene views, target views, vertex indices):
// anything that would make a stage read or write out of bounds is an InputError naming the
// field, raised before the stage runs. Nothing here allocates unless it throws.
#pragma once
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>

#include <string_view>
#include <vector>

#include "render/frame.hpp"

namespace zraster::detail {

// The scene's consistency, its size against options.limits (the frame's memory with
// `target_samples` pixels and samples of targets the frame allocates), and every array of every
// mesh an instance uses; fills frame.meshes (bounds computed where the view has none) and
// frame.mesh_flags. Vertex indices are checked by the front end and check_indices.
void validate_scene(Frame& frame, const SceneView& scene, std::string_view source,
                    const RenderOptions& options, std::uint64_t target_samples);

// Mesh m's vertex colors, checked as validate_scene checks them (none or one per position,
// every component finite; an InputError naming the mesh and the color otherwise): their least
// alpha (1 without colors). The classic visibility algorithms check an owning Scene's with it.
float checked_vertex_colors(const SceneView& scene, std::string_view source, std::size_t m);

// The caller's targets with their pitches resolved (0: tightly packed), after checking their
// size against the options, each pitch against a row and their alignment.
TargetViews resolve_targets(const TargetViews& targets, const RenderOptions& options);

// Vertex indices out of range make the scene invalid (see renderer.cpp); after the front end.
void check_indices(Frame& frame);

}  // namespace zraster::detail
