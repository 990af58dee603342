// See assimp_warnings.hpp.
#include "io/assimp_warnings.hpp"

#include <assimp/DefaultLogger.hpp>
#include <assimp/LogStream.hpp>

#include <mutex>
#include <string_view>
#include <utility>

namespace zraster::io {
namespace {

thread_local std::vector<std::string>* t_capture = nullptr;

class RoutingStream : public Assimp::LogStream {
  public:
    void write(const char* message) override {
        if (t_capture != nullptr) t_capture->emplace_back(message);
    }
};

// Assimp's message (a substring of what its logger writes) and what it means for the scene.
struct KnownWarning {
    std::string_view assimp;
    std::string_view meaning;
};
constexpr KnownWarning kKnownWarnings[] = {
    {"3DS: Vertex index overflow",
     "a 3DS face names a vertex past its mesh's vertices: Assimp moved it to the last vertex, "
     "the face may be drawn wrong"},
    {"3DS: Texture coordinate index overflow",
     "a 3DS face names a texture coordinate past its mesh's: Assimp used the last one"},
    {"Material index overflow in 3DS file",
     "a 3DS face names a material the file does not have: drawn with the default material"},
};

void attach_once() {
    static std::once_flag once;
    std::call_once(once, [] {
        // No default streams (no log file, no debugger output): only ours, for warnings.
        Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
        Assimp::DefaultLogger::get()->attachStream(new RoutingStream, Assimp::Logger::Warn);
    });
}

}  // namespace

AssimpWarnings::AssimpWarnings() : outer_(t_capture) {
    attach_once();
    t_capture = &messages_;
}

AssimpWarnings::~AssimpWarnings() {
    t_capture = outer_;
}

std::vector<std::string> AssimpWarnings::take() {
    std::vector<std::pair<std::string_view, std::size_t>> seen;
    for (const std::string& message : messages_) {
        for (const KnownWarning& known : kKnownWarnings) {
            if (message.find(known.assimp) == std::string::npos) continue;
            auto it = seen.begin();
            while (it != seen.end() && it->first != known.meaning) ++it;
            if (it == seen.end())
                seen.emplace_back(known.meaning, 1);
            else
                ++it->second;
        }
    }
    messages_.clear();
    std::vector<std::string> out;
    for (const auto& [meaning, count] : seen)
        out.push_back(std::string(meaning) +
                      (count > 1 ? " (" + std::to_string(count) + " times)" : std::string()));
    return out;
}

}  // namespace zraster::io
