// Wireframe and hidden-line drawing: hidden-line edges are a subset of the wireframe's, and the
// edges behind a cube's front faces do not show.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include "render/render_test_util.hpp"

namespace zraster::test {
namespace {

std::vector<bool> edge_pixels(const RenderTargets& t, glm::u8vec3 color) {
    std::vector<bool> out(std::size_t(t.width) * std::size_t(t.height));
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = t.color[i * 4] == color.x && t.color[i * 4 + 1] == color.y &&
                 t.color[i * 4 + 2] == color.z;
    return out;
}

TEST(Edges, HiddenLineShowsOnlyTheFrontEdgesOfACube) {
    Scene scene = scene_from_meshes({make_box(glm::vec3(1.0f))});
    RenderOptions o;
    o.width = 320;
    o.height = 240;
    Camera camera;
    camera.eye = {4, 3, 5};
    camera.target = {0, 0, 0};
    camera.near = 1;
    camera.far = 20;
    o.camera = camera;
    o.edge_color = {1, 0, 0};  // red: not produced by the grey shading
    o.cull = CullMode::None;
    o.edges = RenderOptions::Edges::Wireframe;
    const auto wire = edge_pixels(render(scene, o).targets, {255, 0, 0});
    o.edges = RenderOptions::Edges::HiddenLine;
    const auto hidden = edge_pixels(render(scene, o).targets, {255, 0, 0});
    std::size_t wire_count = 0, hidden_count = 0, hidden_not_in_wire = 0;
    for (std::size_t i = 0; i < wire.size(); ++i) {
        wire_count += wire[i];
        hidden_count += hidden[i];
        hidden_not_in_wire += hidden[i] && !wire[i];
    }
    EXPECT_EQ(hidden_not_in_wire, 0u);
    // 12 edges of equal length (plus face diagonals, 2 per face, of which 3 faces are hidden):
    // hiding the back 3 faces' edges and diagonals removes a sizeable share of the pixels.
    EXPECT_GT(wire_count, 600u);
    EXPECT_LT(hidden_count, wire_count * 80 / 100);
    EXPECT_GT(hidden_count, wire_count * 40 / 100);

    // The back corner (-1, -1, -1) projects inside the silhouette, behind the front faces:
    // the wireframe draws the three back edges meeting there, hidden-line none of them.
    const glm::dvec4 clip = glm::dmat4(camera.projection_matrix(double(o.width) / o.height)) *
                            camera.view() * glm::dvec4(-1, -1, -1, 1);
    const int bx = int((clip.x / clip.w + 1) * 0.5 * o.width);
    const int by = int((1 - clip.y / clip.w) * 0.5 * o.height);
    int near_corner_wire = 0, near_corner_hidden = 0;
    for (int y = by - 3; y <= by + 3; ++y)
        for (int x = bx - 3; x <= bx + 3; ++x) {
            near_corner_wire += wire[std::size_t(y * o.width + x)];
            near_corner_hidden += hidden[std::size_t(y * o.width + x)];
        }
    EXPECT_GT(near_corner_wire, 5);
    EXPECT_EQ(near_corner_hidden, 0);
}

}  // namespace
}  // namespace zraster::test
