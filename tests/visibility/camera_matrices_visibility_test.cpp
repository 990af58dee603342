// The list-priority algorithms with cameras from matrices and from intrinsics: they take the
// viewer (the BSP tree's eye point or direction, lighting's eye) from the camera's inverse view
// matrix, so the matrices of a look-at camera draw its image bit for bit, orthographic too, and
// a camera's intrinsics are refused for another image size.
#include <zraster/camera.hpp>
#include <zraster/error.hpp>
#include <zraster/scenes.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <string>

namespace zraster {
namespace {

TEST(CameraMatricesVisibility, LookAtMatricesDrawTheLookAtImage) {
    std::vector<Mesh> meshes;
    meshes.push_back(make_torus(0.8f, 0.3f, 16, 10));
    meshes.push_back(make_box(glm::vec3(0.4f)));
    const Scene scene = scene_from_meshes(std::move(meshes));
    RenderOptions o;
    o.width = 96;
    o.height = 72;
    o.threads = 1;
    Camera perspective = orbit_camera({0.0, 0.0, 0.0}, 4.0, 30.0, 35.0, 50.0);
    perspective.near = 1.0;
    perspective.far = 8.0;
    Camera ortho = perspective;
    ortho.projection = Camera::Projection::Orthographic;
    ortho.ortho_height = 3.0;
    const double aspect = double(o.width) / double(o.height);
    for (const Camera& camera : {perspective, ortho})
        for (VisibilityAlgorithm algorithm :
             {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp,
              VisibilityAlgorithm::Warnock}) {
            SCOPED_TRACE(std::string(camera.is_orthographic() ? "orthographic " : "perspective ") +
                         std::to_string(int(algorithm)));
            RenderOptions a = o, b = o;
            a.camera = camera;
            b.camera = Camera::from_matrices(camera.view(), camera.projection_matrix(aspect),
                                             camera.clip_depth_range());
            EXPECT_EQ(b.camera->is_orthographic(), camera.is_orthographic());
            const RenderResult ra = render_with_visibility(scene, a, algorithm);
            const RenderResult rb = render_with_visibility(scene, b, algorithm);
            EXPECT_EQ(ra.targets.color, rb.targets.color);
            EXPECT_EQ(ra.targets.depth, rb.targets.depth);
        }
}

TEST(CameraMatricesVisibility, IntrinsicsForAnotherImageSizeAreRefused) {
    const Scene scene = scene_from_meshes({make_box(glm::vec3(0.5f))});
    RenderOptions o;
    o.width = 64;
    o.height = 48;
    o.camera = Camera::from_intrinsics(Intrinsics{.fx = 60,
                                                  .fy = 60,
                                                  .cx = 40,
                                                  .cy = 30,
                                                  .width = 80,
                                                  .height = 60,
                                                  .near = 0.5,
                                                  .far = 10},
                                       glm::inverse(look_at({2, 1.5, 3}, {0, 0, 0}, {0, 1, 0})),
                                       CameraConvention::OpenGL);
    for (VisibilityAlgorithm algorithm :
         {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp, VisibilityAlgorithm::Warnock}) {
        try {
            render_with_visibility(scene, o, algorithm);
            ADD_FAILURE() << "no InputError";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "camera intrinsics are for 80x60 but the image is 64x48");
        }
    }
    o.width = 80;
    o.height = 60;
    const RenderResult r = render_with_visibility(scene, o, VisibilityAlgorithm::Bsp);
    std::size_t drawn = 0;
    for (const float d : r.targets.depth) drawn += d < 1.0f;
    EXPECT_GT(drawn, 200u);
}

}  // namespace
}  // namespace zraster
