#include "io/confined_io_system.hpp"

#include <algorithm>

namespace zraster::io {

std::string refusal_text(const std::string& line, const std::string& verb) {
    const std::size_t mark = line.find(kAdviceMark);
    if (mark == std::string::npos) return line + ": " + verb;
    return line.substr(0, mark) + ": " + verb + line.substr(mark + 1);
}

bool ConfinedIOSystem::allowed(const char* file) const {
    const ReferencePolicy::Check check = policy_.check(file);
    if (check.verdict == ReferencePolicy::Verdict::Refused) {
        std::string line = "'";
        line.append(file).append("' ").append(check.reason);
        // The verb ("refused", "not read") goes between the cause and the advice.
        line.append(1, kAdviceMark).append(check.advice());
        if (std::find(refusals_.begin(), refusals_.end(), line) == refusals_.end())
            refusals_.push_back(line);
    }
    return check.verdict == ReferencePolicy::Verdict::Readable;
}

bool ConfinedIOSystem::Exists(const char* file) const {
    return allowed(file);
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
    // Only reading is confined; Assimp's importers never write.
    if (!allowed(file)) return nullptr;
    return Assimp::DefaultIOSystem::Open(file, mode);
}

}  // namespace zraster::io
