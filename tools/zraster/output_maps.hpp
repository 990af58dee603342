// Extra outputs of `zraster render`: depth, normal and id maps, encoded as files' bytes (for
// OutputFiles: all of a run's outputs are written together or not at all).
#pragma once
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace zraster::cli {

// Checks an output path before any work: its extension (one of `extensions`, any case), then
// OutputFiles::check (writable, within the name limits, distinct from the run's other outputs),
// so that a bad one fails the run before anything is rendered or written. Nothing for an empty
// path (the output not asked for). InputError names `option`.
void check_output(OutputFiles& outputs, const std::string& path,
                  std::initializer_list<const char*> extensions, const char* option);
// The path's extension in lower case (".npy").
std::string lower_extension(const std::string& path);

// .npy: float32 (height, width) window depth, top row first; .png: 16-bit gray, 65535 = far.
std::vector<std::uint8_t> encode_depth_map(const std::string& path, const RenderTargets& targets);
// PNG, RGB = world normal * 0.5 + 0.5, background black.
std::vector<std::uint8_t> encode_normal_map(const std::string& path, const RenderTargets& targets);
// .npy: int32 (height, width) id of the visible triangle, -1 for background. The id is the
// triangle's index in draw order over the scene: the sum of the triangle counts of the instances
// before it plus its index in its mesh. .png: a false-color picture of the same ids.
std::vector<std::uint8_t> encode_id_map(const std::string& path, const RenderTargets& targets,
                                        const std::vector<std::int64_t>& instance_first_triangle);

}  // namespace zraster::cli
