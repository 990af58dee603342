// The message a loader worker process sends back to its parent (src/io/load_worker.cpp): a
// converted Scene or the reason there is none, in a small versioned binary format. The parent
// trusts nothing in it: decode_worker_message checks every count against the bytes present and
// the load limits before allocating, and every promise of load.hpp (indices in range, one unit
// normal per position, no uvs or colors or one per position, finite values, materials and meshes
// that exist) before returning.
//
// Version 2 added the materials' alpha (alpha_mode, alpha_cutoff, the opacity texture); version 3
// their double_sided flag; version 4 the limit-exceeded kind (a LoadOptions budget's refusal
// keeps the budget's name); version 5 the meshes' vertex colors; version 6 the files the child
// read besides the model.
//
// Layout, all integers and floats little-endian (the host's; parent and child are the same
// binary), no padding:
//
//   header   "ZRWM" | u32 version (6) | u32 kind | u32 0 | u64 payload bytes | payload
//   kind 1   scene:
//              string source | u32 n, n strings (warnings)
//              u32 n, n strings (files read besides the model: absolute paths)
//              u32 n, n textures: u32 width | u32 height | width*height*4 bytes (RGBA8, level 0)
//              u32 n >= 1, n materials: string name | f32 base_color[3] | f32 ambient | f32
//                diffuse | f32 specular[3] | f32 shininess | f32 opacity (in [0, 1]) |
//                u8 alpha_mode (AlphaMode) | f32 alpha_cutoff (in [0, 1]) |
//                u8 double_sided (0 or 1) |
//                u32 base-color texture | u32 opacity texture (textures: ~0 for none)
//              u32 n, n meshes: string name | u32 material | u64 n, n f32[3] positions |
//                u64 n, n f32[3] normals | u64 n, n f32[2] uvs | u64 n, n f32[4] colors (in
//                [0, 1]) | u64 n, n u32 indices
//              u32 n, n instances: u32 mesh | f32[16] transform (column-major) |
//                u8 shading (255: none, else ShadingMode) | string name
//   kind 2   input error: string cause (the file is the parent's)
//   kind 3   internal error: string what
//   kind 4   out of memory (empty payload)
//   kind 5   limit exceeded: string limit (a LoadOptions field: 1 to 64 of [a-z_]) | string cause
//   string   u32 length (at most kMaxWorkerString) | bytes
#pragma once
#include <zraster/load.hpp>
#include <zraster/scene.hpp>

#include "io/loaded_scene.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace zraster::io {

inline constexpr std::uint32_t kWorkerMessageVersion = 6;
inline constexpr std::size_t kWorkerHeaderBytes = 24;
inline constexpr std::size_t kMaxWorkerString = 65536;
inline constexpr int kMaxWorkerTextureSide = 16384;

enum class WorkerMessageKind : std::uint32_t {
    Scene = 1,
    InputError = 2,
    InternalError = 3,
    OutOfMemory = 4,
    LimitExceeded = 5,
};

// The child's side. Strings longer than kMaxWorkerString are cut (names and warnings only).
std::string encode_scene_message(const LoadedScene& loaded);
std::string encode_error_message(WorkerMessageKind kind, const std::string& text);
// A LoadOptions budget's refusal (LimitExceeded): its limit() and cause().
std::string encode_limit_message(const std::string& limit, const std::string& cause);

// The payload length a header announces, or throws InputError(file, ...) if the header is not a
// header of kWorkerMessageVersion (the parent reads the header first to bound what it accepts).
std::uint64_t worker_payload_bytes(std::span<const std::uint8_t> header, const std::string& file);

// The parent's side: the scene, or throws InputError(file, cause) for an error message
// (LimitExceeded(file, limit, cause) for a limit-exceeded message), a
// malformed message ("the importer process sent an invalid result: ...") or an out-of-memory
// message; std::runtime_error for an internal error of the child. Mesh bounds are recomputed.
LoadedScene decode_worker_message(std::span<const std::uint8_t> message, const std::string& file,
                                  const LoadOptions& options);

}  // namespace zraster::io
