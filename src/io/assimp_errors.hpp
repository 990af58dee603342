// Assimp's error messages in the user's terms. Assimp reports a file it cannot read with a
// message about its own internals ("aiMesh::mFaces[40] is a POINT", "Chunk is too large", "No
// suitable reader found for the file format of file ..."); a user needs to know what is wrong
// with the file. The checks of format_structure_check.hpp and declared_counts_check.hpp refuse
// most such files first with messages of their own; what reaches Assimp and fails is translated
// here: a table of Assimp's known messages, and a fallback naming the format. Assimp's text stays
// only as a trailing "(Assimp: ...)" detail.
#pragma once
#include <zraster/error.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace zraster::io {

// The cause for an InputError about `path` that Assimp failed to read with message `text`
// (one line): "truncated: a 3DS chunk declares more bytes than the file holds (Assimp: Chunk is
// too large)".
std::string assimp_error_cause(const std::filesystem::path& path, const std::string& text);

// The Assimp text of a cause assimp_error_cause made (what its "(Assimp: ...)" holds), or
// nullopt for any other cause.
std::optional<std::string> assimp_detail(const std::string& cause);

// The format as messages name it: the extension in capitals ("ASE"), or "3D model".
std::string format_name(const std::filesystem::path& path);

// Assimp ran out of memory (its std::bad_alloc). In the caller's process an InputError like any
// other; a worker process exits instead, and its parent names the budget the importer ran out of
// (load_worker.cpp).
class ImporterOutOfMemory : public InputError {
  public:
    using InputError::InputError;
};

// Throws the InputError for `path` that Assimp failed to read with message `text` (one line):
// assimp_error_cause's, as an ImporterOutOfMemory when Assimp ran out of memory.
[[noreturn]] void throw_assimp_error(const std::filesystem::path& path, const std::string& text);

}  // namespace zraster::io
