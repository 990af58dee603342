// Members of a JSON object that a reader does not know. A misspelt field ("fov" for "fovy",
// "translation" for "translate") would otherwise be skipped and leave a default in place without
// a word: the JSON files zraster reads (--views-json cameras, cells files) refuse it by name.
#pragma once
#include <nlohmann/json.hpp>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace zraster::io {

// The first member of `object`, in its order, whose name is not in `known`; nullopt when every
// one is known or `object` is not an object.
inline std::optional<std::string> unknown_field(const nlohmann::json& object,
                                                std::initializer_list<std::string_view> known) {
    if (!object.is_object()) return std::nullopt;
    for (const auto& [key, value] : object.items())
        if (std::find(known.begin(), known.end(), key) == known.end()) return key;
    return std::nullopt;
}

}  // namespace zraster::io
