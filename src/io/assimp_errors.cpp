#include "io/assimp_errors.hpp"

#include <cctype>
#include <string_view>

namespace zraster::io {

namespace {

constexpr std::string_view kDetail = " (Assimp: ";

struct Translation {
    const char* assimp;  // a part of Assimp's message
    const char* ours;    // "{}" stands for the format's name
};

// The first entry whose `assimp` text occurs in the message applies: specific texts first.
constexpr Translation kTranslations[] = {
    {"No suitable reader found",
     "no importer recognises its contents as a {} file (a wrong extension, or not a 3D model)"},
    {"Failed to determine STL storage representation",
     "neither an ASCII STL (starting with 'solid') nor a binary STL (84 + 50 x triangles bytes)"},
    {"STL: Invalid number of vertices", "malformed ASCII STL: a facet without 3 vertices"},
    {"Normal buffer size does not match",
     "malformed ASCII STL: facets with and without a 'facet normal'"},
    {"STL: unexpected EOF", "truncated: the ASCII STL ends inside a facet"},
    {"STL: file is empty", "no triangles (a binary STL of 0 facets)"},
    {"STL: file is too small", "truncated: too short for a binary STL's 84-byte header"},
    {"Chunk is too large", "truncated: a 3DS chunk declares more bytes than the file holds"},
    {"3DS file is either empty or corrupt", "truncated or not a 3DS file (too short)"},
    {"is a POINT but", "a face of 1 corner (a point) among the mesh's polygons"},
    {"is a LINE but", "a face of 2 corners (a line) among the mesh's polygons"},
    {"mNumIndices is 0",
     "a face without vertex indices (fewer face records than the header declares?)"},
    {"OFF: Header is invalid",
     "not an OFF file: the header (OFF, then the vertex, face and edge counts) is invalid"},
    {"Incorrect magic number", "not a PLY file: it does not start with 'ply'"},
    {"Invalid .ply file", "malformed PLY file"},
    {"malformed XML", "not well-formed XML, as a {} file must be"},
    {"OBJ: Invalid face index", "malformed OBJ file: a face index that is not a valid number"},
    {"FBX-Tokenize", "malformed FBX file (its text cannot be split into tokens)"},
    {"FBX-Parser", "malformed FBX file"},
    {"FBX-DOM", "malformed FBX file"},
    {"GLTF: No scene", "no scene to draw (the glTF file has no \"scene\" and no \"scenes\")"},
    {"Missing section", "malformed glTF file: a section its contents refer to is missing"},
    {"File is too small", "too short to be a {} file"},
    {"Header mismatch", "not a {} file: its header is not the format's"},
    {"magic", "not a {} file: it does not start with the format's signature"},
    {"Magic", "not a {} file: it does not start with the format's signature"},
    {"Signature", "not a {} file: it does not start with the format's signature"},
    {"No meshes loaded", "no meshes in it (is it a {} file?)"},
    {"Unable to open file", "cannot be opened"},
    {"Failed to open", "not a valid {} file: the importer could not open its contents"},
    {"Buffer view with offset/length",
     "malformed {} file: a buffer view reaches past its buffer's data (a buffer without data?)"},
    {"is out of range", "a face names a vertex past the mesh's vertices"},
    {"is already referenced by this node", "malformed {} file: a node places the same mesh twice"},
    {"there are more than one nodes with",
     "malformed {} file: a camera or light is placed by two nodes (a node with two parents?)"},
    {"has the same name as aiMesh::mBones", "malformed {} file: a skin names the same joint twice"},
    {"mAngleInnerCone is larger than",
     "malformed {} file: a spot light's inner cone angle is larger than its outer one"},
    {"Empty node animation channel",
     "malformed {} file: an animation channel without keys (its bones or skeleton are "
     "inconsistent: a bone its own parent, or no skeleton frame?)"},
    {"mNumChannels is 0",
     "malformed {} file: an animation without channels (its bones or skeleton are "
     "inconsistent: a missing or looping parent, or no skeleton?)"},
    {"Validation failed", "malformed {} file: the importer made an inconsistent scene of it"},
};

// Assimp's own words as the detail after ours, in the user's terms: none for its validation's
// texts, which name its data structures ("aiNode::mMeshes[1]"); its source file and line cut;
// a number it cannot parse quoted alone (it quoted the rest of the file).
std::string assimp_detail_text(std::string text) {
    if (text.find("Validation failed") != std::string::npos) return {};
    for (std::size_t at = text.find("::m"); at != std::string::npos;
         at = text.find("::m", at + 3)) {
        std::size_t start = at;
        while (start > 0 && std::isalnum(static_cast<unsigned char>(text[start - 1]))) --start;
        if (text.compare(start, 2, "ai") == 0) return {};
    }
    if (const std::size_t file = text.find(" (File: "); file != std::string::npos)
        if (const std::size_t end = text.find(')', file); end != std::string::npos)
            text.erase(file, end + 1 - file);
    const std::string_view parse = "Cannot parse string \"";
    if (const std::size_t at = text.find(parse); at != std::string::npos) {
        const std::size_t first = at + parse.size();
        const std::size_t quote = text.find('"', first);
        std::size_t word_end = first;
        while (word_end < text.size() && word_end < quote && text[word_end] != ' ' &&
               text[word_end] != '?' && text[word_end] != '\n')
            ++word_end;
        if (quote != std::string::npos && word_end < quote)
            text.replace(word_end, quote - word_end, "");
    }
    return std::string(kDetail) + text + ")";
}

std::string with_format(std::string_view text, const std::string& format) {
    std::string out(text);
    if (const std::size_t at = out.find("{}"); at != std::string::npos) out.replace(at, 2, format);
    return out;
}

// `GLTF: could not open referenced file "missing.bin"`: the file, quoted.
std::optional<std::string> quoted_reference(const std::string& text) {
    const std::string_view marker = "could not open referenced file \"";
    const std::size_t at = text.find(marker);
    if (at == std::string::npos) return std::nullopt;
    const std::size_t first = at + marker.size();
    const std::size_t last = text.find('"', first);
    if (last == std::string::npos) return std::nullopt;
    return text.substr(first, last - first);
}

}  // namespace

std::string format_name(const std::filesystem::path& path) {
    std::string name = path.extension().string();
    if (name.size() <= 1) return "3D model";
    name.erase(0, 1);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

std::string assimp_error_cause(const std::filesystem::path& path, const std::string& text) {
    // The importer's allocation failed: the file expands past the memory the process may use, in
    // a part of the format no budget counts (a C++ exception's name says nothing to a user).
    if (text.find("bad_alloc") != std::string::npos)
        return "the importer ran out of memory reading it: it expands past the memory this "
               "process may use, in a part of the " +
               format_name(path) + " format zraster does not count before reading";
    const std::string detail = assimp_detail_text(text);
    if (const std::optional<std::string> reference = quoted_reference(text))
        return "the file it refers to, '" + *reference + "', is missing or cannot be read" + detail;
    const std::string format = format_name(path);
    for (const Translation& t : kTranslations)
        if (text.find(t.assimp) != std::string::npos) return with_format(t.ours, format) + detail;
    return "malformed or unsupported " + format + " file" + detail;
}

void throw_assimp_error(const std::filesystem::path& path, const std::string& text) {
    const std::string cause = assimp_error_cause(path, text);
    if (text.find("bad_alloc") != std::string::npos)
        throw ImporterOutOfMemory(path.string(), cause);
    throw InputError(path.string(), cause);
}

std::optional<std::string> assimp_detail(const std::string& cause) {
    const std::size_t at = cause.rfind(kDetail);
    if (at == std::string::npos || !cause.ends_with(")")) return std::nullopt;
    const std::size_t first = at + kDetail.size();
    return cause.substr(first, cause.size() - 1 - first);
}

}  // namespace zraster::io
