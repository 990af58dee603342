// The drawing stage of the list-priority algorithms (painter's, BSP): polygons filled back to
// front on a Canvas, every one of them whether a later one hides it or not. That overdraw is
// their cost beyond the order itself (a million coincident triangles filled 1.3 x 10^9 pixels,
// 50 s), so the pixels filled are counted against painted_fragment_budget, and progress is
// reported as the polygons are drawn.
#pragma once
#include <cstdint>
#include <string>

#include "visibility/canvas.hpp"

namespace zraster::visibility_detail {

class BackToFront {
  public:
    // `algorithm` names the caller in the refusal; `polygons` is how many will be drawn
    // (progress).
    BackToFront(Canvas& canvas, const RenderOptions& options, const char* algorithm,
                std::uint64_t polygons)
        : canvas_(canvas),
          options_(options),
          algorithm_(algorithm),
          polygons_(polygons),
          budget_(painted_fragment_budget(options.limits, options.width, options.height)) {}

    // Throws LimitExceeded ("max_painted_fragments") once more pixels than the budget are
    // filled (drawn, or cut out by an alpha test).
    void draw(const ScreenPolygon& polygon) {
        canvas_.draw(polygon);
        ++drawn_;
        const std::uint64_t filled = canvas_.fragments() + canvas_.alpha_discarded();
        if (filled > budget_)
            throw LimitExceeded(
                "", "max_painted_fragments",
                std::string(algorithm_) + ": more than " + std::to_string(budget_) +
                    " pixels filled drawing " + std::to_string(drawn_) + " of " +
                    std::to_string(polygons_) + " polygons back to front at " +
                    std::to_string(options_.width) + "x" + std::to_string(options_.height) +
                    " (the budget; every polygon is filled, hidden or not): too many polygons "
                    "overlap");
        if (options_.progress != nullptr && (drawn_ & 1023) == 0 && polygons_ > 0) {
            const double fraction = double(drawn_) / double(polygons_);
            options_.progress->report("drawing back to front", fraction < 1.0 ? fraction : 1.0);
        }
    }

  private:
    Canvas& canvas_;
    const RenderOptions& options_;
    const char* algorithm_;
    std::uint64_t polygons_;
    std::uint64_t budget_;
    std::uint64_t drawn_ = 0;
};

}  // namespace zraster::visibility_detail
