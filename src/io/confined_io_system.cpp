#include "io/confined_io_system.hpp"

#include "io/mtl_for_assimp.hpp"
#include "io/uri_escapes.hpp"

#include <assimp/MemoryIOWrapper.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <system_error>

namespace zraster::io {

std::string refusal_text(const std::string& line, const std::string& verb) {
    const std::size_t mark = line.find(kAdviceMark);
    if (mark == std::string::npos) return line + ": " + verb;
    return line.substr(0, mark) + ": " + verb + line.substr(mark + 1);
}

bool ConfinedIOSystem::allowed(const std::string& file) const {
    const ReferencePolicy::Check check = policy_.check(file);
    if (check.verdict == ReferencePolicy::Verdict::Refused) {
        std::string line = "'";
        line.append(file).append("' ").append(check.reason);
        // The verb ("refused", "not read") goes between the cause and the advice.
        line.append(1, kAdviceMark).append(check.advice());
        if (std::find(refusals_.begin(), refusals_.end(), line) == refusals_.end())
            refusals_.push_back(line);
    }
    if (check.verdict != ReferencePolicy::Verdict::Readable) return false;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (!ec && size > max_bytes_) {
        std::string line = "'";
        line.append(file).append("' is ").append(std::to_string(size));
        line.append(" bytes, more than max_file_bytes (").append(std::to_string(max_bytes_));
        line.append(")").append(1, kAdviceMark);
        if (std::find(refusals_.begin(), refusals_.end(), line) == refusals_.end())
            refusals_.push_back(line);
        return false;
    }
    return true;
}

void ConfinedIOSystem::decode_uris_of(const std::string& model) {
    // Assimp's glTF importers join a URI to the text before the model's last slash.
    const std::size_t slash = model.find_last_of('/');
    uri_folder_ = slash == std::string::npos ? std::string() : model.substr(0, slash + 1);
}

std::string ConfinedIOSystem::on_disk(const char* file) const {
    const std::string text(file);
    if (!uri_folder_ || !text.starts_with(*uri_folder_)) return text;
    return uri_file(std::filesystem::path(*uri_folder_), text.substr(uri_folder_->size())).string();
}

bool ConfinedIOSystem::Exists(const char* file) const {
    return allowed(on_disk(file));
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
    // Only reading is confined; Assimp's importers never write.
    const std::string name = on_disk(file);
    if (!allowed(name)) return nullptr;
    Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(name.c_str(), mode);
    if (stream == nullptr || !rewrite_libraries_ || obj_model_ == name) return stream;
    std::string text(stream->FileSize(), '\0');
    const std::size_t read = text.empty() ? 0 : stream->Read(text.data(), 1, text.size());
    Close(stream);
    text.resize(read);
    const std::optional<std::string> rewritten = mtl_for_assimp(text);
    const std::string& served = rewritten ? *rewritten : text;
    auto* bytes = new std::uint8_t[served.size() + 1];  // owned by the stream
    std::memcpy(bytes, served.data(), served.size());
    return new Assimp::MemoryIOStream(bytes, served.size(), true);
}

}  // namespace zraster::io
