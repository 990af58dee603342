#include "io/obj_material_libraries.hpp"

#include "io/mtl_numbers_check.hpp"
#include "io/text_util.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <system_error>

#include <fstream>

namespace zraster::io {

bool directive(const std::string& line, std::string_view keyword, std::string& argument) {
    const std::string_view text = trim(line);
    if (!text.starts_with(keyword) || text.size() <= keyword.size()) return false;
    if (text[keyword.size()] != ' ' && text[keyword.size()] != '\t') return false;
    argument = std::string(trim(text.substr(keyword.size())));
    return !argument.empty();
}

namespace {

// The `newmtl` names into `names`; returns how many statements (a name defined twice is two
// materials to Assimp).
std::size_t read_material_names(const std::filesystem::path& mtl, std::set<std::string>& names) {
    std::ifstream in(mtl);
    std::string line, name;
    std::size_t count = 0;
    while (std::getline(in, line))
        if (directive(line, "newmtl", name)) {
            names.insert(name);
            ++count;
        }
    return count;
}

}  // namespace

MaterialLibraryChoice resolve_material_library(const std::filesystem::path& obj_path,
                                               const std::string& library,
                                               const ReferencePolicy& policy) {
    const std::filesystem::path named = obj_path.parent_path() / library;
    const ReferencePolicy::Check check = policy.check(named);
    if (check.verdict == ReferencePolicy::Verdict::Readable) return {named, false, {}};
    const std::string cause =
        check.verdict == ReferencePolicy::Verdict::Refused
            ? "not read: " + named.string() + " " + check.reason + check.advice()
            : "not found";
    std::filesystem::path substitute = obj_path;
    substitute.replace_extension(".mtl");
    if (policy.check(substitute).verdict == ReferencePolicy::Verdict::Readable)
        return {substitute, true,
                "material library '" + library + "' " + cause + ", using '" +
                    substitute.filename().string() + "'"};
    return {std::nullopt, false,
            "material library '" + library + "' " + cause + ", using the default material"};
}

std::uintmax_t max_material_library_bytes(const LoadOptions& options) {
    return std::min<std::uintmax_t>(options.max_file_bytes, std::uintmax_t{64} << 20);
}

void check_material_library(const std::filesystem::path& obj_path, const std::filesystem::path& mtl,
                            const LoadOptions& options) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(mtl, ec);
    const std::uintmax_t limit = max_material_library_bytes(options);
    if (ec || size <= limit) return;
    throw LimitExceeded(obj_path.string(), "max_file_bytes",
                        "its material library " + mtl.string() + " is " + std::to_string(size) +
                            " bytes, more than the " + std::to_string(limit) +
                            " bytes a material library may have");
}

void note_named_textures(const std::filesystem::path& mtl, const ReferencePolicy& policy) {
    std::ifstream in(mtl, std::ios::binary);
    std::string line;
    std::set<std::string> seen;
    const auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (std::getline(in, line)) {
        const std::string_view text = trim(line);
        std::size_t word = 0;
        while (word < text.size() && !is_blank(text[word])) ++word;
        const std::string_view keyword = text.substr(0, word);
        if (!keyword.starts_with("map_") && keyword != "bump" && keyword != "disp" &&
            keyword != "decal" && keyword != "refl" && keyword != "norm")
            continue;
        std::size_t last = text.size();
        while (last > word && !is_blank(text[last - 1])) --last;
        if (last == word) continue;
        const std::string name(text.substr(last));
        if (seen.insert(name).second) (void)policy.check(mtl.parent_path() / name);
    }
}

void check_material_count(const std::filesystem::path& obj_path, std::size_t count,
                          const LoadOptions& options) {
    if (count <= options.max_materials) return;
    throw LimitExceeded(obj_path.string(), "max_materials",
                        "its material libraries define " + std::to_string(count) +
                            " materials, more than max_materials (" +
                            std::to_string(options.max_materials) + ")");
}

ObjMaterialLibraries scan_obj_material_libraries(const std::filesystem::path& obj_path,
                                                 const ReferencePolicy& policy,
                                                 const LoadOptions& options) {
    ObjMaterialLibraries result;
    std::size_t materials = 0;

    std::ifstream in(obj_path);
    std::string line, library;
    std::set<std::string> seen;
    while (std::getline(in, line)) {
        if (!directive(line, "mtllib", library) || !seen.insert(library).second) continue;
        const MaterialLibraryChoice choice = resolve_material_library(obj_path, library, policy);
        if (!choice.warning.empty()) result.warnings.push_back(choice.warning);
        if (!choice.file) continue;
        check_material_library(obj_path, *choice.file, options);
        materials += read_material_names(*choice.file, result.defined_materials);
        check_material_count(obj_path, materials, options);
        check_mtl_numbers(obj_path, *choice.file, &result.notices);
        note_named_textures(*choice.file, policy);
        result.dissolve.read(*choice.file);
    }
    return result;
}

}  // namespace zraster::io
