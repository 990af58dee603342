// glTF 2.0 byte ranges, checked before Assimp reads them: Debian's Assimp 5.2.5 copies an
// accessor's bytes without checking that they lie inside its buffer view and buffer (a
// heap-buffer-overflow found by fuzz_load_gltf), and allocates a GLB chunk's declared length
// before reading it.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace zraster::io {

// The deepest a glTF document's JSON may nest arrays and objects: Assimp's parser recurses per
// level (200,000 levels crashed it); glTF's own structure needs fewer than 20.
inline constexpr std::size_t kMaxGltfJsonDepth = 256;

// Throws InputError("malformed glTF file: its JSON nests ... more than 256 levels deep") first.
// `json` is the glTF document (a .gltf file, or a GLB's JSON chunk); `glb_binary` the length of
// a GLB's BIN chunk, if any. Buffers with a uri are sized from their data: URI or from the file
// beside `path`. Throws InputError("malformed glTF file: ...") for a buffer view
// outside its buffer, an accessor (sparse parts included) outside its buffer view, or a buffer
// declaring more bytes than its data holds, and for a node graph that places more than
// options.max_instances meshes (nodes sharing children multiply: a small file can describe
// billions) or holds a cycle. Buffer files are sized only where options' reference policy lets
// them be read (reference_policy.hpp). Leaves documents it cannot parse to Assimp.
void check_gltf_bounds(const std::filesystem::path& path, const std::string& json,
                       std::optional<std::uint64_t> glb_binary, const LoadOptions& options);

}  // namespace zraster::io
