// The showcase scene ("builtin:default"): what the pipeline does, in one picture.
//  - A torus through a box, a sphere sunk into the ground, the torus dipping into the ground:
//    depth-buffered intersections that no object-order sort could draw correctly.
//  - A large checkerboard ground seen at a grazing angle up to the horizon: perspective-correct
//    texturing (straight checker lines) and mipmapping (no moire in the distance).
//  - Three identical coarse spheres shaded Flat, Gouraud and Phong, left to right: facets, then
//    smooth color with a smeared highlight, then a crisp per-pixel highlight.
#include "scenes/default_scene.hpp"

#include "scenes/building.hpp"

#include <zraster/scenes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <memory>

namespace zraster {

namespace {

Material make_material(std::string name, glm::vec3 base_color, float specular, float shininess) {
    Material m;
    m.name = std::move(name);
    m.base_color = base_color;
    m.specular = glm::vec3(specular);
    m.shininess = shininess;
    return m;
}

std::uint32_t add_mesh(Scene& scene, Mesh mesh, std::string name, std::uint32_t material) {
    mesh.name = std::move(name);
    mesh.material = material;
    scene.meshes.push_back(std::move(mesh));
    return std::uint32_t(scene.meshes.size() - 1);
}

void add_instance(Scene& scene, std::uint32_t mesh, const glm::mat4& transform, std::string name,
                  std::optional<ShadingMode> shading = std::nullopt) {
    Instance instance;
    instance.mesh = mesh;
    instance.transform = transform;
    instance.shading = shading;
    instance.name = std::move(name);
    scene.instances.push_back(std::move(instance));
}

glm::mat4 translation(float x, float y, float z) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z));
}

}  // namespace

Scene make_default_scene() {
    Scene scene;
    scene.name = "builtin:default";
    scene.materials = {Material{}};

    // Ground: 8x8 squares of 32 texels per texture, repeated 20 times: 0.5-unit squares. Large
    // enough that its far edge sits just below the horizon from builtin_camera.
    Material ground = make_material("ground", glm::vec3(1.0f), 0.05f, 16.0f);
    ground.base_color_texture = std::make_shared<const Texture>(make_checkerboard_texture(
        8, 32, glm::u8vec4(225, 225, 220, 255), glm::u8vec4(55, 60, 75, 255)));
    scene.materials.push_back(std::move(ground));
    scene.materials.push_back(make_material("red", {0.80f, 0.22f, 0.18f}, 0.3f, 32.0f));
    scene.materials.push_back(make_material("gold", {0.95f, 0.72f, 0.25f}, 0.6f, 64.0f));
    scene.materials.push_back(make_material("green", {0.30f, 0.68f, 0.36f}, 0.35f, 48.0f));
    scene.materials.push_back(make_material("blue", {0.25f, 0.45f, 0.85f}, 0.6f, 48.0f));

    const auto ground_mesh = add_mesh(scene, make_ground_plane(80.0f, 20.0f), "ground", 1);
    const auto box_mesh = add_mesh(scene, make_box(glm::vec3(0.7f)), "box", 2);
    const auto torus_mesh = add_mesh(scene, make_torus(0.85f, 0.22f, 48, 24), "torus", 3);
    const auto big_sphere = add_mesh(scene, make_uv_sphere(1.1f, 32, 64), "sphere", 4);
    // Coarse on purpose: 12x24 facets make flat, Gouraud and Phong shading clearly different.
    const auto small_sphere = add_mesh(scene, make_uv_sphere(0.55f, 12, 24), "coarse_sphere", 5);

    // The ground reaches far behind the scene (towards -z) and a little behind the camera.
    add_instance(scene, ground_mesh, translation(0.0f, 0.0f, -25.0f), "ground");

    const glm::mat4 box =
        glm::rotate(translation(-3.2f, 0.7f, -2.2f), glm::radians(-30.0f), glm::vec3(0, 1, 0));
    add_instance(scene, box_mesh, box, "box");
    // Standing upright (ring in the xy plane), its left arc through the box, its bottom through
    // the ground.
    const glm::mat4 torus = glm::rotate(
        glm::rotate(translation(-2.25f, 0.95f, -2.1f), glm::radians(-20.0f), glm::vec3(0, 1, 0)),
        glm::radians(90.0f), glm::vec3(1, 0, 0));
    add_instance(scene, torus_mesh, torus, "torus");

    add_instance(scene, big_sphere, translation(3.0f, 0.45f, -2.4f), "sunken_sphere");

    const ShadingMode modes[3] = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};
    const char* names[3] = {"flat_sphere", "gouraud_sphere", "phong_sphere"};
    for (int k = 0; k < 3; ++k)
        add_instance(scene, small_sphere, translation(1.4f * float(k - 1), 0.55f, 2.6f), names[k],
                     modes[k]);
    return scene;
}

std::optional<Camera> builtin_camera(std::string_view spec) {
    if (const auto building = detail::parse_building_spec(spec))
        return detail::building_camera(*building);
    if (spec != "builtin:default") return std::nullopt;
    // Low and looking slightly down: the ground recedes to the horizon in the upper part of a
    // 16:9 frame, with all objects in view.
    Camera camera;
    camera.eye = {0.0, 3.0, 8.5};
    camera.target = {0.0, 0.5, -0.5};
    camera.up = {0.0, 1.0, 0.0};
    camera.fovy_degrees = 40.0;
    camera.near = 0.2;
    camera.far = 150.0;
    return camera;
}

}  // namespace zraster
