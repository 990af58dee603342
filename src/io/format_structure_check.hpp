// Checks of a file's structure made before Assimp reads it, for the formats whose structure is
// cheap to check: what Assimp would refuse with a message about its own internals ("Failed to
// determine STL storage representation", "Chunk is too large", "No suitable reader found") is
// refused here in the user's terms, naming what is wrong and where.
//
//   glTF   the text is JSON (line and column of the first error), an object with an "asset" of
//          version 2.x
//   GLB    the header ("glTF", version 2) and a first chunk of JSON that parses
//   STL    binary (84 + 50 x triangles bytes, the count at byte 80) or ASCII ("solid"); in ASCII,
//          every facet has 3 vertices and ends before the file does
//   3DS    the main chunk (0x4D4D) and the chunks nested in it fit in their parents and the file
//
// Other formats pass unchecked (the declared counts of PLY and OFF: declared_counts_check.hpp).
#pragma once
#include <cstdint>
#include <filesystem>

namespace zraster::io {

// Throws InputError(file, cause) for a file of one of the formats above whose structure is
// broken; does nothing otherwise. Reads at most the file (file_size bytes, already checked
// against LoadOptions::max_file_bytes).
void check_format_structure(const std::filesystem::path& path, std::uintmax_t file_size);

}  // namespace zraster::io
