// Files a model names that zraster may not read itself (a glTF image only an unsupported
// material extension uses, such as KHR_materials_clearcoat's), noted as read: a command's outputs
// must not replace any file the model names.
#pragma once
#include <filesystem>

#include "io/reference_policy.hpp"

namespace zraster::io {

// Every glTF image given by URI (not a data: URI), resolved beside the model and checked by
// `policy`, which lists the readable ones in files_read(). Does nothing for other files.
void note_gltf_images(const std::filesystem::path& model, const ReferencePolicy& policy);

}  // namespace zraster::io
