// The work Assimp's triangulation does on a file's polygons, bounded before Assimp reads it.
// Assimp clips the ears of a polygon of more than four corners in time quadratic in its corners
// (one face of 32,767 corners took 12 s, 300 such faces over a minute, whatever the triangle
// budget): a face of n corners counts n^2 against LoadOptions::max_triangulation_work.
// Triangles and quads (split without a search) do not count.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace zraster::io {

class TriangulationBudget {
  public:
    TriangulationBudget(const std::filesystem::path& path, const LoadOptions& options)
        : path_(path), max_(options.max_triangulation_work) {}

    // A face of `corners` corners, `where` naming it ("line 7", "face 12"). Throws
    // LimitExceeded(limit "max_triangulation_work") naming it once the sum is past the budget.
    void add(std::uint64_t corners, const std::string& where);

  private:
    const std::filesystem::path& path_;
    std::uint64_t max_;
    std::uint64_t used_ = 0;
};

}  // namespace zraster::io
