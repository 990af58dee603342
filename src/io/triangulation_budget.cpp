// See triangulation_budget.hpp.
#include "io/triangulation_budget.hpp"

#include <zraster/error.hpp>

namespace zraster::io {

void TriangulationBudget::add(std::uint64_t corners, const std::string& where) {
    if (corners <= 4) return;
    // Corners are at most 2^32 (the callers' counts): the square and the sum do not overflow
    // before the budget, at most 2^64 - 1, is checked.
    const std::uint64_t work = corners * corners;
    used_ = work > UINT64_MAX - used_ ? UINT64_MAX : used_ + work;
    if (used_ > max_)
        throw LimitExceeded(
            path_.string(), "max_triangulation_work",
            where + ": a polygon of " + std::to_string(corners) +
                " corners takes the triangulation's work (corners^2 summed over "
                "the polygons of more than 4 corners) past max_triangulation_work (" +
                std::to_string(max_) + ")");
}

}  // namespace zraster::io
