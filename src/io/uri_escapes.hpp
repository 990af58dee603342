// URIs in model files (glTF buffers and images) may carry %XX escapes ("my%20model.bin" names
// "my model.bin"). Importers join them to the model's folder as written; zraster reads the file
// the URI names: the name as written when such a file exists (a name may hold a '%'), else the
// decoded one.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace zraster::io {

// `uri` with its %XX escapes decoded; nullopt when it has none, or when one is %00 (a name
// cannot hold a NUL: the URI is taken as written).
std::optional<std::string> percent_decoded(std::string_view uri);

// The file `uri` names inside `folder`: folder / uri when that exists, else folder / the decoded
// uri when it has escapes, else folder / uri.
std::filesystem::path uri_file(const std::filesystem::path& folder, const std::string& uri);

}  // namespace zraster::io
