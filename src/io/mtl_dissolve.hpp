// MTL's two spellings of a material's opacity: `d` (dissolve: the opacity) and `Tr`
// (transparency: 1 - opacity). Assimp's MTL reader keeps whichever statement comes last; zraster,
// like tinyobjloader, lets `d` win when a material has both, because exporters disagree on what
// `Tr` means (some write `Tr 1` beside `d 1` for an opaque material). This scan finds the `d`
// values a later `Tr` hid from Assimp.
#pragma once
#include <zraster/material.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace zraster::io {

class MtlDissolve {
  public:
    // Reads one material library; libraries are read in the order Assimp reads them (the
    // `mtllib` statements' order), as a material named again in a later library is the same one.
    void read(const std::filesystem::path& mtl);

    // The `d` value of `material` when a `Tr` statement came after its last `d`.
    std::optional<float> hidden_dissolve(const std::string& material) const;

    // Material::opacity from the hidden `d` value, if any (clamped to [0, 1] as Assimp's opacity
    // is, with a warning appended to `warnings` when that changes it).
    void apply(Material& material, std::vector<std::string>& warnings) const;

  private:
    struct Statements {
        std::optional<float> dissolve;  // the last `d`
        bool transparency_after = false;
    };
    std::map<std::string, Statements> materials_;
};

}  // namespace zraster::io
