// Ogre XML meshes (.mesh.xml) as Assimp reads them: it reserves what the counts declare (a
// faces count of 2,000,000,000 ran it out of memory), reads face indices without checking them
// against the vertices (drawn as garbage), and reads the prefix of a number ("1,5" as 1, "1e5x"
// as 1e5). A scan of the XML refuses them first, naming the element.
#pragma once
#include <string>
#include <string_view>

namespace zraster::io {

// Throws InputError(file, "malformed Ogre XML file: ...") for a faces count or vertexcount that
// is not the number of <face> or <vertex> elements, a face index that is not one of its
// submesh's vertices (its own geometry's, or the shared geometry's), and a coordinate
// (position, normal, texcoord) that is not a number.
void check_ogre_xml(std::string_view document, const std::string& file);

}  // namespace zraster::io
