// See explain_budget.hpp.
#include "explain_budget.hpp"

#include <zraster/error.hpp>

#include <limits>

namespace zraster::cli {

void check_explain_pixels(std::uint64_t pictures, std::uint64_t pixels_each, std::uint64_t limit,
                          const std::string& what, const std::string& fewer) {
    const bool overflows =
        pixels_each != 0 && pictures > std::numeric_limits<std::uint64_t>::max() / pixels_each;
    const std::uint64_t total =
        overflows ? std::numeric_limits<std::uint64_t>::max() : pictures * pixels_each;
    if (total <= limit) return;
    // Counted before the pictures (and the frames they show) are made.
    throw LimitExceeded("--size", "max_explain_pixels",
                        what + " are " + std::to_string(total) +
                            " pixels of pictures, more than explain's limit of " +
                            std::to_string(limit) + " (lower --size" +
                            (fewer.empty() ? "" : ", " + fewer) + ")");
}

}  // namespace zraster::cli
