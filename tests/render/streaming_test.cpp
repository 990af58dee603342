// Large frames (RendererConfig::streaming_threshold_bytes) write the target rows with non-temporal
// stores: the images are those of ordinary copies. Every target, rows of any alignment (a width
// that is not a multiple of the tile), tiles drawn and tiles left clear, forward and deferred
// shading.
#include <gtest/gtest.h>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <cstring>
#include <limits>

#include "render/frame.hpp"

namespace zraster {
namespace {

RenderResult render_with_threshold(const Scene& scene, const RenderOptions& o,
                                   std::size_t threshold) {
    Renderer renderer(RendererConfig{threshold});
    return renderer.render(scene, o);
}

void expect_same_targets(const Scene& scene, const RenderOptions& o) {
    const RenderResult copied =
        render_with_threshold(scene, o, std::numeric_limits<std::size_t>::max());
    const RenderResult streamed = render_with_threshold(scene, o, 1);  // every frame streams
    ASSERT_EQ(copied.targets.depth.size(), streamed.targets.depth.size());
    EXPECT_EQ(std::memcmp(copied.targets.depth.data(), streamed.targets.depth.data(),
                          copied.targets.depth.size() * sizeof(float)),
              0);
    EXPECT_EQ(copied.targets.color, streamed.targets.color);
    EXPECT_EQ(copied.targets.primitive_id, streamed.targets.primitive_id);
}

TEST(Streaming, StreamedStoresGiveTheSameImages) {
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
    // Close up, most vertices outside the view (their outcodes matter).
    Camera close;
    close.eye = {0.4, 0.3, 1.3};
    close.fovy_degrees = 30.0;
    o.camera = close;
    expect_same_targets(sphere, o);
    o.camera.reset();
    o.color_target = true;
    o.id_targets = true;  // the pixel-by-pixel path beside the rows
    expect_same_targets(make_procedural_scene("city:300"), o);
}

}  // namespace
}  // namespace zraster
