// See gltf_document.hpp.
#include "io/gltf_document.hpp"

#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string_view>

namespace zraster::io {

namespace {

std::uint32_t header_u32(const std::array<char, 20>& b, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k)
        v |= std::uint32_t(static_cast<unsigned char>(b[at + k])) << (8 * k);
    return v;
}

}  // namespace

// The glTF document: a GLB's JSON chunk, or a file of JSON whole; empty for anything else.
std::string gltf_document(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 20> header{};
    if (!in.read(header.data(), header.size())) return {};
    if (std::string_view(header.data(), 4) == "glTF") {
        if (header_u32(header, 4) != 2 || std::string_view(header.data() + 16, 4) != "JSON")
            return {};
        std::string text(header_u32(header, 12), '\0');
        if (!in.read(text.data(), std::streamsize(text.size()))) return {};
        return text;
    }
    // Assimp reads a glTF under any name: a JSON object is taken as one (the parse decides).
    const std::string_view start(header.data(), header.size());
    const std::size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || start[first] != '{') return {};
    in.seekg(0);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace zraster::io
