// Rendering a mesh held in the application's own memory into the application's own image:
// an interleaved vertex buffer and 16-bit indices in, an RGBA8 image with padded rows and a
// float depth image out, nothing copied either way. Writes the color image as a binary PPM.
//
//   render_from_memory [out.ppm]
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>
#include <zraster/version.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <vector>

namespace {

// The application's vertex layout: position, normal and a color it does not give zraster.
struct Vertex {
    float position[3];
    float normal[3];
    std::uint32_t rgba;
};

// A UV sphere of radius 1 in the application's own buffers.
void make_sphere(int stacks, int slices, std::vector<Vertex>& vertices,
                 std::vector<std::uint16_t>& indices) {
    const float pi = 3.14159265358979f;
    for (int i = 0; i <= stacks; ++i) {
        const float theta = pi * float(i) / float(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float phi = 2.0f * pi * float(j) / float(slices);
            const float x = std::sin(theta) * std::cos(phi), y = std::cos(theta),
                        z = std::sin(theta) * std::sin(phi);
            vertices.push_back({{x, y, z}, {x, y, z}, 0xffffffffu});
        }
    }
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const auto a = std::uint16_t(i * (slices + 1) + j), b = std::uint16_t(a + slices + 1);
            indices.insert(indices.end(), {a, std::uint16_t(a + 1), b, b, std::uint16_t(a + 1),
                                           std::uint16_t(b + 1)});
        }
}

}  // namespace

int main(int argc, char** argv) try {
    std::vector<Vertex> vertices;
    std::vector<std::uint16_t> indices;
    make_sphere(48, 96, vertices, indices);

    // Views of the application's buffers: pointer, count, stride.
    zraster::MeshView mesh;
    mesh.positions = {vertices[0].position, vertices.size(), sizeof(Vertex)};
    mesh.normals = {vertices[0].normal, vertices.size(), sizeof(Vertex)};
    mesh.indices = {indices.data(), indices.size(), zraster::IndexType::UInt16};
    mesh.bounds = zraster::Bounds3f{glm::vec3(-1.0f), glm::vec3(1.0f)};
    zraster::Material material;
    material.base_color = {0.9f, 0.45f, 0.2f};
    zraster::InstanceView instance;  // identity transform
    zraster::SceneView scene{{&mesh, 1}, {&material, 1}, {&instance, 1}};

    zraster::RenderOptions options;
    options.width = 320;
    options.height = 240;
    zraster::Camera camera;
    camera.eye = {0.0, 1.0, 3.5};
    camera.target = {0.0, 0.0, 0.0};
    camera.near = 0.5;
    camera.far = 10.0;
    options.camera = camera;

    // The application's images: RGBA rows padded to 1,536 bytes, depth tightly packed.
    const std::size_t color_pitch = 1536;
    std::vector<std::uint8_t> color(color_pitch * std::size_t(options.height));
    std::vector<float> depth(std::size_t(options.width) * std::size_t(options.height));
    zraster::TargetViews targets;
    targets.width = options.width;
    targets.height = options.height;
    targets.color = color.data();
    targets.color_pitch = color_pitch;
    targets.depth = depth.data();

    zraster::Renderer renderer;  // keeps its memory and threads from frame to frame
    const zraster::RenderStats& stats = renderer.render(scene, options, targets);

    std::size_t covered = 0;
    for (float d : depth) covered += d < 1.0f;
    std::printf("zraster %s: %llu triangles in, %llu rasterized, %zu of %d pixels covered\n",
                zraster::kVersionString, static_cast<unsigned long long>(stats.triangles_in),
                static_cast<unsigned long long>(stats.triangles_rasterized), covered,
                options.width * options.height);

    const char* path = argc > 1 ? argv[1] : "render_from_memory.ppm";
    if (std::FILE* f = std::fopen(path, "wb")) {
        std::fprintf(f, "P6\n%d %d\n255\n", options.width, options.height);
        for (int y = 0; y < options.height; ++y)
            for (int x = 0; x < options.width; ++x)
                std::fwrite(&color[std::size_t(y) * color_pitch + std::size_t(x) * 4], 1, 3, f);
        std::fclose(f);
    }
    // The sphere fills a good part of the image; a blank image means something is wrong.
    return covered > 10000 ? 0 : 1;
} catch (const std::exception& e) {
    std::fprintf(stderr, "render_from_memory: %s\n", e.what());
    return 2;
}
