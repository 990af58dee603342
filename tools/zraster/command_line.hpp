// Shared pieces of the zraster command: value parsers and exit codes.
#pragma once
#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <string>

namespace zraster::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitSomeFilesFailed = 3;  // `zraster batch`: the others were rendered

// The option that raises a library limit (LimitExceeded::limit()), as advice to append to its
// message ("; raise it with --max-bsp-polygons N"); empty for a limit without one.
std::string limit_advice(const std::string& limit);

// "N", "NK", "NM", "NG", "NT" (powers of 1024; "KiB", "KB", "k" and the like accepted too).
// Throws InputError naming `option`.
std::uint64_t parse_byte_size(const std::string& option, const std::string& text);

// The instanced vertices of `scene` (what a camera fit copies) within the renderer's vertex limit
// (RenderLimits::max_vertices) and its frame within `max_frame_bytes` (check_frame_memory,
// without targets), checked before anything is copied: LimitExceeded otherwise.
void check_instanced_vertices(const Scene& scene, std::uint64_t max_frame_bytes);

// Enough digits (17 significant) to read back the same double; -0 written as 0. For the flag
// values the command makes and the numbers of the JSON it writes.
std::string exact_number(double x);

// "X,Y,Z" -> vec3; throws InputError naming the option on malformed or non-finite values.
glm::dvec3 parse_vec3(const std::string& option, const std::string& text);
glm::dvec4 parse_vec4(const std::string& option, const std::string& text);
// "WxH" with 1 <= W, H <= limit.
glm::ivec2 parse_size(const std::string& option, const std::string& text, int limit);

// --threads: 0 (every hardware thread) up to kMaxThreadsPerHardwareThread times the hardware
// threads (render.hpp). More is clamped to that, as the library does, with a warning on stderr;
// negative is an InputError.
int checked_thread_count(const std::string& option, int requested);

// "auto" | "forward" | "deferred" (CLI11 checks the value first).
ShadingStrategy shading_strategy(const std::string& name);

// A mesh file path, or a procedural spec (builtin:NAME, sphere:N, city:N[:SEED], soup:N[:SEED]).
// Assimp runs in a worker process (LoadIsolation::WorkerProcess) unless set_load_in_process(true)
// (the --load-in-process flag; run_zraster sets it for every run). The loader's warnings are
// printed to stderr ("warning: ..."), and kept in *warnings when it is given. The files the model
// names and the loader read (textures, buffers, material libraries) are made inputs of *outputs
// when it is given, so that no output of the run replaces them (an InputError names both), and
// appended to *files_read when that is given.
Scene load_scene_or_procedural(const std::string& spec,
                               std::vector<std::string>* warnings = nullptr,
                               OutputFiles* outputs = nullptr,
                               std::vector<std::filesystem::path>* files_read = nullptr);
// What an output is called when it would replace a file the model names.
std::string file_named_by(const std::string& model);
void set_load_in_process(bool in_process);
// The --allow-outside-references flag: a model's external files may be read from anywhere
// (LoadOptions::allow_outside_references).
void set_allow_outside_references(bool allow);
// The --max-instances option (LoadOptions::max_instances).
void set_max_instances(std::size_t max_instances);
// The --max-materials option (LoadOptions::max_materials).
void set_max_materials(std::size_t max_materials);
// The command's --max-triangles (LoadOptions::max_triangles; `zraster batch` sets its own).
void set_max_load_triangles(std::size_t max_triangles);
// --max-triangulation-work (LoadOptions::max_triangulation_work).
void set_max_triangulation_work(std::uint64_t max_work);
// The importer's time in its worker process (LoadOptions::worker_timeout_seconds; by default
// LoadOptions::kWorkerTimeoutFromFile).
void set_max_load_seconds(double seconds);
// --max-geometry-memory (LoadOptions::max_geometry_bytes).
void set_max_geometry_bytes(std::size_t max_bytes);
// --max-texture-side and --max-texture-memory (LoadOptions::max_texture_side, max_texture_bytes).
void set_texture_limits(int max_side, std::size_t max_bytes);
// The LoadOptions of the settings above, the rest as LoadOptions' defaults.
LoadOptions command_load_options();

}  // namespace zraster::cli
