// An engine-style occlusion culling loop with zraster::OcclusionBuffer: each frame, draw the big
// occluders (here a wall), then test every object's bounding box and draw only what may be seen.
//
//   occlusion_culling
#include <zraster/camera.hpp>
#include <zraster/occlusion_buffer.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <vector>

int main() try {
    const int width = 640, height = 360;
    zraster::OcclusionBuffer buffer(width, height);

    // The occluder: a wall 20 wide and 6 high at z = 0, facing +z (two triangles).
    const std::vector<glm::vec3> wall = {{-10, 0, 0}, {10, 0, 0}, {10, 6, 0}, {-10, 6, 0}};
    const std::vector<std::uint32_t> wall_indices = {0, 1, 2, 0, 2, 3};

    // Objects: a row of unit boxes behind the wall (z = -5) and one in front of it (z = +3).
    struct Object {
        glm::vec3 position;
        bool behind_wall;
    };
    std::vector<Object> objects;
    for (int i = -4; i <= 4; ++i) objects.push_back({{2.0f * float(i), 1.0f, -5.0f}, true});
    objects.push_back({{0.0f, 1.0f, 3.0f}, false});
    const zraster::Bounds3f unit_box{glm::vec3(-0.5f), glm::vec3(0.5f)};

    int wrong = 0;
    for (int frame = 0; frame < 4; ++frame) {
        // The camera walks sideways in front of the wall, at eye height.
        const float x = -3.0f + 2.0f * float(frame);
        const glm::mat4 view = glm::lookAt(glm::vec3(x, 1.7f, 12.0f), glm::vec3(x, 1.7f, 0.0f),
                                           glm::vec3(0, 1, 0));
        const glm::mat4 projection =
            glm::perspective(glm::radians(60.0f), float(width) / float(height), 0.1f, 100.0f);
        const glm::mat4 view_projection = projection * view;

        buffer.clear();
        buffer.render_occluders(wall, wall_indices, view_projection);

        int drawn = 0, occluded = 0, outside = 0;
        for (const Object& object : objects) {
            const glm::mat4 model = glm::translate(glm::mat4(1.0f), object.position);
            switch (buffer.test_box(unit_box, view_projection * model)) {
                case zraster::OcclusionResult::Visible:
                    ++drawn;  // an engine would draw the object here
                    break;
                case zraster::OcclusionResult::Occluded:
                    ++occluded;
                    wrong += !object.behind_wall;  // something in front is never hidden
                    break;
                case zraster::OcclusionResult::OutsideView:
                    ++outside;
                    break;
            }
        }
        std::printf("frame %d: %d drawn, %d occluded, %d outside the view\n", frame, drawn,
                    occluded, outside);
        if (occluded == 0) wrong += 1;  // the wall hides the boxes behind it
    }
    std::printf("occlusion buffer: %s kernels\n", zraster::OcclusionBuffer::simd_target());
    return wrong == 0 ? 0 : 1;
} catch (const std::exception& e) {
    std::fprintf(stderr, "occlusion_culling: %s\n", e.what());
    return 2;
}
