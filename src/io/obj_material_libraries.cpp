#include "io/obj_material_libraries.hpp"

#include "io/mtl_numbers_check.hpp"
#include "io/text_util.hpp"

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

void read_material_names(const std::filesystem::path& mtl, std::set<std::string>& names) {
    std::ifstream in(mtl);
    std::string line, name;
    while (std::getline(in, line))
        if (directive(line, "newmtl", name)) names.insert(name);
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

ObjMaterialLibraries scan_obj_material_libraries(const std::filesystem::path& obj_path,
                                                 const ReferencePolicy& policy) {
    ObjMaterialLibraries result;

    std::ifstream in(obj_path);
    std::string line, library;
    std::set<std::string> seen;
    while (std::getline(in, line)) {
        if (!directive(line, "mtllib", library) || !seen.insert(library).second) continue;
        const MaterialLibraryChoice choice = resolve_material_library(obj_path, library, policy);
        if (!choice.warning.empty()) result.warnings.push_back(choice.warning);
        if (!choice.file) continue;
        check_mtl_numbers(obj_path, *choice.file, &result.notices);
        read_material_names(*choice.file, result.defined_materials);
        result.dissolve.read(*choice.file);
    }
    return result;
}

}  // namespace zraster::io
