// The benchmark workload of docs/bench-scenes.md besides its scenes (zraster/scenes.hpp): the
// three shadings and the render state every benchmark of zraster and of the llvmpipe reference
// uses, so that their figures compare frame for frame.
#pragma once
#include <zraster/export.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <string>

namespace zraster {

// The three shadings of docs/bench-scenes.md ("Render state and shading").
enum class BenchMode { Depth, Flat, Phong };

// "depth" | "flat" | "phong"; throws InputError naming `option` otherwise.
ZRASTER_API BenchMode parse_bench_mode(const std::string& option, const std::string& text);
ZRASTER_API const char* bench_mode_name(BenchMode mode);

// Replaces every material by the benchmark's (default Material for phong, base color
// (0.9, 0.6, 0.3) for flat) and drops per-instance shading overrides, so a mesh file's own
// materials cannot change the workload.
ZRASTER_API void apply_bench_shading(Scene& scene, BenchMode mode);

// The benchmark render state: LESS, clear 1, back faces culled (CCW front) unless !cull,
// background 0.2, two-sided Blinn-Phong with a local viewer; depth mode has no color target.
// The camera is left unset (fit_camera framing), and the meshes are declared static.
ZRASTER_API RenderOptions bench_render_options(BenchMode mode, int width, int height, int threads,
                                               bool cull);

// Threads render() actually uses for `threads` (0 = all hardware threads).
ZRASTER_API int effective_thread_count(int threads);

}  // namespace zraster
