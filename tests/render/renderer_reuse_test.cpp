// A Renderer kept across frames gives, frame after frame, the images of one-off renders: its
// targets, threads and the record of which tiles still hold the cleared values from the
// previous frame (empty tiles are not rewritten) never leak one frame into the next, whatever
// changes between them (scene, background, depth format, targets, size, edges).
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <string>

namespace zraster {
namespace {

struct Step {
    std::string what;
    const Scene* scene;
    RenderOptions options;
};

void expect_same_targets(const RenderTargets& got, const RenderTargets& want) {
    EXPECT_EQ(got.width, want.width);
    EXPECT_EQ(got.height, want.height);
    EXPECT_EQ(got.color, want.color);
    EXPECT_EQ(got.depth, want.depth);
    EXPECT_TRUE(got.normal == want.normal);
    EXPECT_EQ(got.instance_id, want.instance_id);
    EXPECT_EQ(got.primitive_id, want.primitive_id);
}

TEST(RendererReuse, EveryFrameIsTheOneOffImage) {
    // The soup covers every tile; the small sphere leaves most of them empty, so frames after
    // the soup must clear tiles the soup drew, and frames after the sphere may skip them.
    const Scene soup = make_procedural_scene("soup:3000:5");
    const Scene sphere = make_procedural_scene("sphere:400");
    RenderOptions base;
    base.width = 320;
    base.height = 200;
    base.camera = fit_camera(sphere.world_positions());
    base.camera->eye *= 3.0;  // the sphere small in the middle (it is centered on the origin)
    base.camera->far *= 4.0;
    RenderOptions soup_options = base;
    soup_options.camera.reset();

    std::vector<Step> steps;
    steps.push_back({"soup", &soup, soup_options});
    steps.push_back({"sphere after soup", &sphere, base});
    steps.push_back({"sphere again", &sphere, base});
    RenderOptions other_background = base;
    other_background.background = {0.9f, 0.1f, 0.3f};
    steps.push_back({"other background", &sphere, other_background});
    steps.push_back({"background back", &sphere, base});
    RenderOptions d16 = base;
    d16.depth_format = DepthFormat::D16;
    steps.push_back({"D16", &sphere, d16});
    RenderOptions ids = base;
    ids.id_targets = true;
    ids.normal_target = true;
    steps.push_back({"ids and normals", &sphere, ids});
    steps.push_back({"ids and normals again", &sphere, ids});
    RenderOptions reversed = base;
    reversed.camera->reversed_z = true;
    steps.push_back({"reversed z (another clear depth)", &sphere, reversed});
    RenderOptions wire = base;
    wire.edges = RenderOptions::Edges::Wireframe;
    steps.push_back({"wireframe", &sphere, wire});
    steps.push_back({"after wireframe", &sphere, base});
    RenderOptions wider = base;
    wider.width = 333;
    steps.push_back({"another size", &sphere, wider});
    steps.push_back({"size back", &sphere, base});
    steps.push_back({"soup again", &soup, soup_options});

    Renderer renderer;
    for (const Step& step : steps) {
        SCOPED_TRACE(step.what);
        const RenderResult want = render(*step.scene, step.options);
        const RenderResult& got = renderer.render(*step.scene, step.options);
        expect_same_targets(got.targets, want.targets);
        if (HasFailure()) return;
    }
}

}  // namespace
}  // namespace zraster
