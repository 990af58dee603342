#include "support/test_support.hpp"

namespace zraster::test {

std::filesystem::path shared_data(const std::string& relative) {
    return std::filesystem::path(ZRASTER_SHARED_DATA) / relative;
}

bool have_shared_data() {
    return std::filesystem::is_directory(std::filesystem::path(ZRASTER_SHARED_DATA) / "meshes");
}

std::filesystem::path temp_dir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("zraster-test-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace zraster::test
