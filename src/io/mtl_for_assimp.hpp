// A material library as Assimp's MTL reader should read it. Two valid MTL statements it misreads:
// `decal file.png` (a decal map) is taken for `d` followed by the word "ecal", which fails the
// import in Assimp's words; and a color of one number (`Kd 0.5`), which the MTL specification
// reads as gray (0.5, 0.5, 0.5), becomes (0.5, 0, 0). Both OBJ paths read materials with Assimp
// through ConfinedIOSystem, which hands it the library as rewritten here.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace zraster::io {

// The warning for a library with `decal` statements (the statements are dropped).
inline constexpr std::string_view kDecalIgnored = "decal maps are not supported; ignored";

// Whether the line is a `decal` statement (dropped for Assimp).
bool is_decal_statement(std::string_view line);

// `text` with each `decal` statement replaced by an empty line (line numbers stay) and each color
// statement of one number (Ka, Kd, Ks, Ke, Tf) given it three times; nullopt when there is none.
std::optional<std::string> mtl_for_assimp(std::string_view text);

}  // namespace zraster::io
