// Target rows written with non-temporal stores (large frames, see target_stream_threshold) give
// the same images as ordinary copies: every target, rows of any alignment (a width that is not
// a multiple of the tile), tiles drawn and tiles left clear, forward and deferred shading.
#include <gtest/gtest.h>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <cstring>
#include <limits>

#include "render/frame.hpp"

namespace zraster {
namespace {

// Restores the threshold when a test ends, however it ends.
struct ThresholdOverride {
    std::size_t saved = detail::target_stream_threshold();
    explicit ThresholdOverride(std::size_t value) { detail::target_stream_threshold() = value; }
    ~ThresholdOverride() { detail::target_stream_threshold() = saved; }
};

RenderResult render_with_threshold(const Scene& scene, const RenderOptions& o,
                                   std::size_t threshold) {
    const ThresholdOverride override(threshold);
    return render(scene, o);
}

void expect_same_targets(const Scene& scene, const RenderOptions& o) {
    const RenderResult copied =
        render_with_threshold(scene, o, std::numeric_limits<std::size_t>::max());
    const RenderResult streamed = render_with_threshold(scene, o, 0);
    ASSERT_EQ(copied.targets.depth.size(), streamed.targets.depth.size());
    EXPECT_EQ(std::memcmp(copied.targets.depth.data(), streamed.targets.depth.data(),
                          copied.targets.depth.size() * sizeof(float)),
              0);
    EXPECT_EQ(copied.targets.color, streamed.targets.color);
    EXPECT_EQ(copied.targets.primitive_id, streamed.targets.primitive_id);
}

TEST(TargetStream, StreamedRowsGiveTheSameImages) {
    const Scene sphere = make_procedural_scene("sphere:20000");
    RenderOptions o;
    o.width = 333;  // rows start at every alignment
    o.height = 217;
    o.color_target = true;
    expect_same_targets(sphere, o);  // deferred Phong, depth and color
    o.strategy = ShadingStrategy::Forward;
    expect_same_targets(sphere, o);
    o.strategy = ShadingStrategy::Auto;
    o.color_target = false;  // depth only
    expect_same_targets(sphere, o);
    o.color_target = true;
    o.id_targets = true;  // the pixel-by-pixel path beside the rows
    expect_same_targets(make_procedural_scene("city:300"), o);
}

}  // namespace
}  // namespace zraster
