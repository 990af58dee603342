// mesh_file_extensions: see include/zraster/load.hpp.
#include <zraster/load.hpp>

#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>

namespace zraster {
namespace {

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::vector<std::string> list_extensions() {
    // Assimp's list is "*.3d;*.3ds;...;*.mesh.xml;...". Only asking: no file is read here.
    std::string list;
    Assimp::Importer().GetExtensionList(list);
    std::vector<std::string> extensions{".obj"};  // zraster's own reader
    std::size_t start = 0;
    while (start < list.size()) {
        const std::size_t end = std::min(list.find(';', start), list.size());
        std::string item = list.substr(start, end - start);
        if (item.starts_with("*")) item.erase(0, 1);
        if (item.size() > 1 && item.starts_with(".")) extensions.push_back(lower(item));
        start = end + 1;
    }
    std::sort(extensions.begin(), extensions.end());
    extensions.erase(std::unique(extensions.begin(), extensions.end()), extensions.end());
    return extensions;
}

}  // namespace

const std::vector<std::string>& mesh_file_extensions() {
    static const std::vector<std::string> extensions = list_extensions();
    return extensions;
}

bool has_mesh_file_extension(const std::filesystem::path& path) {
    const std::string name = lower(path.filename().string());
    for (const std::string& extension : mesh_file_extensions())
        if (name.size() > extension.size() && name.ends_with(extension)) return true;
    return false;
}

}  // namespace zraster
