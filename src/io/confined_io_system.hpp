// Assimp's file access, confined by a ReferencePolicy: every file an importer opens besides the
// model (glTF buffers, OBJ material libraries, ...) must be one the policy allows. A refused file
// looks missing to Assimp, and its refusal is kept so that the error (or warning) names it.
#pragma once
#include <assimp/DefaultIOSystem.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/reference_policy.hpp"

namespace zraster::io {

// Separates a refusal's cause from its advice in ConfinedIOSystem's lines (refusal_text()).
inline constexpr char kAdviceMark = '\x01';

// "'path' CAUSE: VERB (ADVICE)" from a line ConfinedIOSystem collected: the advice only for a
// file outside the model's folder (ReferencePolicy::Check::advice()).
std::string refusal_text(const std::string& line, const std::string& verb);

class ConfinedIOSystem : public Assimp::DefaultIOSystem {
  public:
    // `refusals` collects one line per refused file ("'path' is outside ..." with the advice
    // after kAdviceMark: read them with refusal_text()); it must outlive the importer that owns
    // this IOSystem.
    ConfinedIOSystem(ReferencePolicy policy, std::vector<std::string>& refusals)
        : policy_(std::move(policy)), refusals_(refusals) {}

    // OBJ imports: every file Assimp opens besides `model` is a material library, handed to it
    // as mtl_for_assimp() rewrites it.
    void rewrite_material_libraries(std::string model) {
        obj_model_ = std::move(model);
        rewrite_libraries_ = true;
    }

    // Refuses files larger than `max_bytes` (LoadOptions::max_file_bytes): Assimp reads a
    // referenced file whole (a LightWave scene's 20 GiB object hung the loader).
    void limit_file_size(std::uintmax_t max_bytes) { max_bytes_ = max_bytes; }

    // A model whose importer joins URIs to its folder as written (glTF): a file missing under
    // that name but present under the URI's decoded name (%XX escapes) is the decoded one.
    void decode_uris_of(const std::string& model);

    bool Exists(const char* file) const override;
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

  private:
    bool allowed(const std::string& file) const;
    std::string on_disk(const char* file) const;  // the file `file` names (decode_uris_of)
    ReferencePolicy policy_;
    std::vector<std::string>& refusals_;
    bool rewrite_libraries_ = false;
    std::string obj_model_;
    std::uintmax_t max_bytes_ = ~std::uintmax_t{0};
    std::optional<std::string> uri_folder_;  // the model's folder as the importer spells it
};

}  // namespace zraster::io
