// OpenGEX (.ogex) meshes as Debian's Assimp 5.2.5 reads them: it trusts the index arrays (an index
// past the vertices failed an assertion, one equal to their count was read from past the array
// and drawn), vertex arrays of other lengths than the positions', index arrays of other than 3
// indices a face and an empty position array (all crashed it), and it parses nested structures
// recursively. A scan of the OpenDDL text refuses them first, naming the line.
#pragma once
#include <string>
#include <string_view>

namespace zraster::io {

// Throws InputError(file, "malformed OpenGEX file: line N: ...") for, in each Mesh: a vertex
// array with no elements or another count than the position array's, an index array whose
// elements are not 3 indices or whose indices are negative or not below the vertex count; and for
// structures nested more than 1,000 deep. Text it cannot follow is left to the importer.
void check_opengex(std::string_view text, const std::string& file);

}  // namespace zraster::io
