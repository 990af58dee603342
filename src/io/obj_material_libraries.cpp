#include "io/obj_material_libraries.hpp"

#include "io/text_util.hpp"

#include <fstream>

namespace zraster::io {

namespace {

// The rest of a line after `keyword` and whitespace, if the line starts with it.
bool directive(const std::string& line, std::string_view keyword, std::string& argument) {
    const std::string_view text = trim(line);
    if (!text.starts_with(keyword) || text.size() <= keyword.size()) return false;
    if (text[keyword.size()] != ' ' && text[keyword.size()] != '\t') return false;
    argument = std::string(trim(text.substr(keyword.size())));
    return !argument.empty();
}

void read_material_names(const std::filesystem::path& mtl, std::set<std::string>& names) {
    std::ifstream in(mtl);
    std::string line, name;
    while (std::getline(in, line))
        if (directive(line, "newmtl", name)) names.insert(name);
}

bool is_file(const std::filesystem::path& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
}

}  // namespace

ObjMaterialLibraries scan_obj_material_libraries(const std::filesystem::path& obj_path) {
    ObjMaterialLibraries result;
    const std::filesystem::path dir = obj_path.parent_path();
    std::filesystem::path fallback = obj_path;
    fallback.replace_extension(".mtl");

    std::ifstream in(obj_path);
    std::string line, library;
    std::set<std::string> seen;
    while (std::getline(in, line)) {
        if (!directive(line, "mtllib", library) || !seen.insert(library).second) continue;
        const std::filesystem::path candidate = dir / library;
        if (is_file(candidate)) {
            read_material_names(candidate, result.defined_materials);
        } else if (is_file(fallback)) {
            result.warnings.push_back("material library '" + library + "' not found, using '" +
                                      fallback.filename().string() + "'");
            read_material_names(fallback, result.defined_materials);
        } else {
            result.warnings.push_back("material library '" + library +
                                      "' not found, using the default material");
        }
    }
    return result;
}

}  // namespace zraster::io
