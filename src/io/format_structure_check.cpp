#include "io/format_structure_check.hpp"

#include "io/json_errors.hpp"
#include "io/obj_number_token.hpp"

#include <zraster/error.hpp>

#include "io/text_util.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zraster::io {

namespace {

using json = nlohmann::json;

// Files up to this size are read whole for the checks; larger ones (rare for the formats checked
// here) are left to Assimp.
constexpr std::uintmax_t kMaxCheckedBytes = std::uintmax_t{256} << 20;

std::string lower_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

std::string whole_file(const std::filesystem::path& path, std::uintmax_t size) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    return bytes;
}

std::uint32_t little_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int b = 0; b < 4; ++b)
        v |= std::uint32_t{static_cast<std::uint8_t>(bytes[at + std::size_t(b)])} << (8 * b);
    return v;
}

std::uint16_t little_u16(std::string_view bytes, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<std::uint8_t>(bytes[at]) |
                                      (static_cast<std::uint8_t>(bytes[at + 1]) << 8));
}

std::string hex16(std::uint16_t id) {
    static const char* digits = "0123456789ABCDEF";
    std::string out = "0x";
    for (int shift = 12; shift >= 0; shift -= 4) out += digits[(id >> shift) & 15];
    return out;
}

// The specification: a loader must refuse a file whose "minVersion" it does not support. Assimp
// reads glTF 2.0 (a newer minor version may use what 2.0 readers misread) and ignores the member.
void check_gltf_min_version(const std::string& file, const json& asset) {
    const auto min_version = asset.find("minVersion");
    if (min_version == asset.end()) return;
    const std::string v = min_version->is_string() ? min_version->get<std::string>() : "";
    const std::size_t dot = v.find('.');
    const auto digits = [&](std::size_t from, std::size_t to) {
        return to > from && to - from <= 9 &&
               std::all_of(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(to),
                           [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dot == std::string::npos || !digits(0, dot) || !digits(dot + 1, v.size()))
        throw InputError(file,
                         "its asset's \"minVersion\" is not a MAJOR.MINOR version string "
                         "such as \"2.0\"");
    const long major = std::stol(v.substr(0, dot)), minor = std::stol(v.substr(dot + 1));
    if (major > 2 || (major == 2 && minor > 0))
        throw InputError(file, "its asset's \"minVersion\" is " + v + ": it needs a glTF " + v +
                                   " reader, zraster reads glTF 2.0");
}

// A glTF document (the .gltf text, or a GLB's JSON chunk: `chunk`): JSON, an object, an asset
// of version 2.N. glTF 1.0 (2015, superseded in 2017) is refused although Assimp has an importer
// for it: that importer reports a malformed file as "no suitable reader" and checks little, and
// zraster's own checks (gltf_bounds_check.cpp) read the 2.0 layout only.
void check_gltf_json(const std::string& file, std::string_view text, bool chunk) {
    const std::string json_text = chunk ? "its JSON chunk" : "the JSON";
    json document;
    try {
        document = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        throw InputError(file, (chunk ? "its JSON chunk is not valid JSON: " : "not valid JSON: ") +
                                   json_error_text(e));
    }
    if (!document.is_object())
        throw InputError(file,
                         "not a glTF file: " + json_text + " is not an object (a glTF file's is)");
    const auto asset = document.find("asset");
    if (asset == document.end() || !asset->is_object())
        throw InputError(file, "not a glTF file: " + json_text +
                                   " has no \"asset\" object (every glTF file has one)");
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        throw InputError(file, "not a glTF file: its \"asset\" has no \"version\" string");
    const std::string v = version->get<std::string>();
    if (v.starts_with("1.") || v == "1")
        throw InputError(file, "glTF " + one_line(v.substr(0, 32)) +
                                   " is not supported, only glTF 2.0 is (convert the file to 2.0)");
    // The specification's form is MAJOR.MINOR, digits only: "2.0abc", "2" or "02.0" is not a
    // version Assimp should be left to guess at.
    const bool two_dot_n =
        v.size() > 2 && v.starts_with("2.") &&
        std::all_of(v.begin() + 2, v.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!two_dot_n) {
        // Quoted as written, blanks included (" 2.0" is not "2.0").
        std::string shown = v.substr(0, 32);
        for (char& c : shown)
            if ((c >= 0 && c < ' ') || c == 0x7f) c = '?';
        throw InputError(
            file, "glTF version '" + shown + "' is not supported, only glTF 2.N (such as 2.0) is");
    }
    check_gltf_min_version(file, *asset);
}

void check_glb_structure(const std::string& file, const std::string& bytes) {
    if (bytes.size() < 12)
        throw InputError(file,
                         "truncated: a binary glTF (GLB) file starts with a 12-byte "
                         "header, this file has " +
                             std::to_string(bytes.size()) + " bytes");
    if (!bytes.starts_with("glTF"))
        throw InputError(file, "not a binary glTF (GLB) file: it does not start with 'glTF'");
    const std::uint32_t version = little_u32(bytes, 4);
    if (version == 1)
        throw InputError(file,
                         "GLB version 1 (binary glTF 1.0) is not supported, only GLB 2 (glTF "
                         "2.0) is (convert the file to 2.0)");
    if (version != 2)
        throw InputError(file,
                         "GLB version " + std::to_string(version) + " is not supported (2 is)");
    if (bytes.size() < 20)
        throw InputError(file, "truncated: the GLB header is not followed by a chunk (the JSON)");
    const std::uint32_t length = little_u32(bytes, 12);
    if (std::string_view(bytes).substr(16, 4) != "JSON")
        throw InputError(file, "malformed GLB file: its first chunk is not the JSON chunk");
    if (length > bytes.size() - 20) return;  // declared_counts_check names it
    check_gltf_json(file, std::string_view(bytes).substr(20, length), true);
}

// STL, as Assimp tells the two apart: binary when the size is exactly 84 + 50 x the count at
// byte 80; else ASCII when it starts with "solid" (after blanks).
void check_stl_structure(const std::string& file, const std::string& bytes) {
    const std::size_t size = bytes.size();
    if (size >= 84) {
        const std::uint64_t declared = little_u32(bytes, 80);
        if (84 + 50 * declared == size) {
            if (declared == 0)
                throw InputError(file, "no triangles (a binary STL whose header declares 0)");
            return;
        }
    }
    std::size_t at = 0;
    while (at < size &&
           (bytes[at] == ' ' || bytes[at] == '\t' || bytes[at] == '\r' || bytes[at] == '\n'))
        ++at;
    if (bytes.compare(at, 5, "solid") != 0 || at + 5 >= size) {
        std::string cause =
            "neither an ASCII STL (starting with 'solid') nor a binary STL (84 + 50 x triangles "
            "bytes";
        if (size >= 84) {
            const std::uint64_t declared = little_u32(bytes, 80);
            cause += "; its header declares " + std::to_string(declared) + " triangles, " +
                     std::to_string(84 + 50 * declared) + " bytes";
        }
        throw InputError(file, cause + "), this file has " + std::to_string(size) + " bytes");
    }
    // A binary STL whose 80-byte header happens to start with "solid" and whose size is not
    // 84 + 50 x its count: Assimp reads it as ASCII and finds nothing; say what it is.
    if (size >= 84 && bytes.find('\0') < 84) {
        const std::uint64_t declared = little_u32(bytes, 80);
        throw InputError(file,
                         "truncated or malformed binary STL (its header starts with "
                         "'solid', but it holds binary data): its header declares " +
                             std::to_string(declared) + " triangles, 84 + 50 x " +
                             std::to_string(declared) + " = " + std::to_string(84 + 50 * declared) +
                             " bytes, this file has " + std::to_string(size));
    }
    // ASCII: Assimp fails when a facet has fewer than 3 vertices, and drops every vertex after
    // the third with no more than a log line (the facet then is not what the file says): both
    // are refused here.
    std::size_t line = 1, facet_line = 0;
    std::uint64_t facets = 0, complete = 0;
    int vertices = 3;
    auto end_facet = [&] {
        if (facets != 0 && vertices != 3)
            throw InputError(file, "malformed ASCII STL: facet " + std::to_string(facets) +
                                       " (line " + std::to_string(facet_line) + ") has " +
                                       std::to_string(vertices) + " vertices; STL facets have 3");
        if (facets != 0) ++complete;
    };
    bool in_facet = false;
    int numbers_due =
        0;  // after "vertex" or "normal": its three numbers (Assimp read "1,5" as 1.5)
    while (at < size) {
        const char c = bytes[at];
        if (c == '\n') ++line;
        // (Every blank the token loop stops at, \v and \f too: a blank left here was an empty
        // token and the loop never moved on; fuzz_load_stl found it.)
        if (std::isspace(static_cast<unsigned char>(c)) || c == '\0') {
            ++at;
            continue;
        }
        std::size_t end = at;
        while (end < size && !std::isspace(static_cast<unsigned char>(bytes[end])) &&
               bytes[end] != '\0')
            ++end;
        const std::string_view token(bytes.data() + at, end - at);
        if (numbers_due > 0) {
            if (!is_number_word(token))
                throw InputError(file, "malformed ASCII STL: line " + std::to_string(line) + ": " +
                                           not_a_number(token) +
                                           " (vertices and normals are 3 "
                                           "decimal numbers)");
            --numbers_due;
            at = end;
            continue;
        }
        if (token == "vertex" || token == "normal") numbers_due = 3;
        if (token == "facet") {
            if (in_facet) end_facet();
            in_facet = true;
            ++facets;
            facet_line = line;
            vertices = 0;
        } else if (token == "vertex" && in_facet) {
            // A fourth is refused at once (no count to keep past it).
            if (++vertices > 3) end_facet();
        } else if (token == "endfacet" && in_facet) {
            end_facet();
            in_facet = false;
        } else if (token.starts_with("endsolid")) {
            if (in_facet) end_facet();
            in_facet = false;
        }
        at = end;
    }
    if (in_facet && vertices < 3)
        throw InputError(file, "truncated: the ASCII STL ends inside facet " +
                                   std::to_string(facets) + " (line " + std::to_string(facet_line) +
                                   ") after " + std::to_string(vertices) + " of its 3 vertices");
    if (complete == 0 && !(in_facet && vertices == 3))
        throw InputError(file, "no triangles (an ASCII STL without a complete facet)");
}

// 3DS: chunks of [u16 id][u32 size, header included]. Assimp reads each chunk header of the
// main chunk and of the chunks below that it descends into, and fails ("Chunk is too large")
// when a size is under 6 or reaches past the end of the file.
bool is_3ds_container(std::uint16_t id) {
    switch (id) {
        case 0x4D4D:  // main
        case 0xC23D:  // main, of a project file
        case 0x3D3D:  // editor
        case 0x4000:  // object (after its name)
        case 0x4100:  // triangle mesh
        case 0xAFFF:  // material
        case 0xB000:  // keyframer
            return true;
        default:
            return false;
    }
}

void check_3ds_structure(const std::string& file, const std::string& bytes) {
    const std::size_t size = bytes.size();
    if (size < 16)
        throw InputError(file, "truncated: " + std::to_string(size) +
                                   " bytes are too few for a 3DS file (a main chunk of 16 or "
                                   "more)");
    const std::uint16_t first = little_u16(bytes, 0);
    if (first != 0x4D4D && first != 0xC23D)
        throw InputError(file,
                         "not a 3DS file: it does not start with the main chunk (0x4D4D), "
                         "but with " +
                             hex16(first));
    // (start, end) of the chunk sequences still to walk; explicit stack, nesting is bounded by
    // the bytes anyway.
    std::vector<std::pair<std::size_t, std::size_t>> pending{{0, size}};
    int walked = 0;
    while (!pending.empty()) {
        auto [at, end] = pending.back();
        pending.pop_back();
        while (end - at >= 6) {
            if (++walked > 1'000'000) return;  // enough for a check
            const std::uint16_t id = little_u16(bytes, at);
            const std::uint32_t declared = little_u32(bytes, at + 2);
            if (declared < 6)
                throw InputError(file, "malformed 3DS file: chunk " + hex16(id) + " at byte " +
                                           std::to_string(at) + " declares " +
                                           std::to_string(declared) +
                                           " bytes, less than its own 6-byte header");
            if (declared > size - at)
                throw InputError(file, "truncated: a 3DS chunk (" + hex16(id) + " at byte " +
                                           std::to_string(at) + ") declares " +
                                           std::to_string(declared) + " bytes, " +
                                           std::to_string(declared - (size - at)) +
                                           " past the end of the file");
            const std::size_t chunk_end = std::min<std::size_t>(at + declared, end);
            if (is_3ds_container(id)) {
                std::size_t content = at + 6;
                if (id == 0x4000) {  // a NUL-terminated name first
                    const std::size_t nul = bytes.find('\0', content);
                    content = nul == std::string::npos || nul >= chunk_end ? chunk_end : nul + 1;
                }
                pending.emplace_back(content, chunk_end);
            }
            at += declared;
            if (at >= end) break;
        }
    }
}

bool starts_with_glb_magic(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    return in.read(magic, 4) && std::string_view(magic, 4) == "glTF";
}

}  // namespace

void check_format_structure(const std::filesystem::path& path, std::uintmax_t file_size) {
    if (file_size > kMaxCheckedBytes) return;
    const std::string extension = lower_extension(path);
    const std::string file = path.string();
    if (extension == ".gltf") {
        const std::string text = whole_file(path, file_size);
        // A .gltf that is in fact a GLB is read as one.
        if (text.starts_with("glTF")) return check_glb_structure(file, text);
        check_gltf_json(file, text, false);
    } else if (extension == ".glb") {
        check_glb_structure(file, whole_file(path, file_size));
    } else if (extension == ".stl") {
        check_stl_structure(file, whole_file(path, file_size));
    } else if (extension == ".3ds") {
        check_3ds_structure(file, whole_file(path, file_size));
    } else if (starts_with_glb_magic(path)) {
        // Under another name: Assimp asks every importer whether it reads the file, and the
        // glTF ones claim it by its magic.
        check_glb_structure(file, whole_file(path, file_size));
    } else if (extension != ".obj" && extension != ".ply" && extension != ".off") {
        // A glTF under another name (x.json): read as one (starts_json_object).
        if (starts_json_object(whole_file(path, std::min<std::uintmax_t>(file_size, 4096))))
            check_gltf_json(file, whole_file(path, file_size), false);
    }
}

}  // namespace zraster::io
