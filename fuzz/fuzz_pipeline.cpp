// libFuzzer target: the pipeline fed raw geometry. The input bytes choose a scene (meshes with
// positions from a palette of hostile values: NaN, +-Inf, +-1e30, FLT_MAX, denormals, signed
// zeros, duplicates of earlier vertices, points on the line through two earlier ones; indices;
// normals, uvs, vertex colors, tiny textures; instances with random, singular and non-finite
// matrices), a camera (or none: fit_camera), and every render option, at sizes up to 96x96.
//
// Oracles besides the sanitizers: render() either returns targets of the right sizes whose
// values are in range (depth in [0, 1], ids naming real instances and triangles) or throws an
// InputError of one line; and the images are bit-identical for 1 thread, 2-3 threads, and a
// Renderer reused from earlier inputs (determinism, include/zraster/render.hpp).
#include <zraster/error.hpp>
#include <zraster/render.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace zraster;

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "zraster fuzz invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

float hostile_float(FuzzedDataProvider& in) {
    static constexpr float kPalette[] = {
        0.0f,
        -0.0f,
        1.0f,
        -1.0f,
        0.5f,
        2.0f,
        -3.0f,
        10.0f,
        1e-3f,
        1e4f,
        1e30f,
        -1e30f,
        FLT_MAX,
        -FLT_MAX,
        FLT_MIN,
        1e-40f,   // denormal
        -1e-45f,  // smallest denormal
        std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(),
        std::numeric_limits<float>::quiet_NaN(),
        0x1p20f,  // the guard band, in pixels
        16384.0f,
        0.1f,
        100.0f,
    };
    switch (in.ConsumeIntegralInRange(0, 3)) {
        case 0:
            return in.PickValueInArray(kPalette);
        case 1:  // any bit pattern
            return in.ConsumeFloatingPoint<float>();
        default:  // ordinary coordinates, where most triangles land on screen
            return in.ConsumeFloatingPointInRange(-4.0f, 4.0f);
    }
}

glm::vec3 hostile_vec3(FuzzedDataProvider& in) {
    const float x = hostile_float(in), y = hostile_float(in), z = hostile_float(in);
    return {x, y, z};
}

double hostile_double(FuzzedDataProvider& in) {
    if (in.ConsumeBool()) return in.ConsumeFloatingPointInRange(-20.0, 20.0);
    return static_cast<double>(hostile_float(in));
}

glm::dvec3 hostile_dvec3(FuzzedDataProvider& in) {
    const double x = hostile_double(in), y = hostile_double(in), z = hostile_double(in);
    return {x, y, z};
}

Mesh make_mesh(FuzzedDataProvider& in) {
    Mesh mesh;
    mesh.name = "fuzz";
    const int vertices = in.ConsumeIntegralInRange(0, 48);
    for (int v = 0; v < vertices; ++v) {
        const auto n = mesh.positions.size();
        switch (n > 1 ? in.ConsumeIntegralInRange(0, 5) : 0) {
            case 4:  // a duplicate
                mesh.positions.push_back(
                    mesh.positions[in.ConsumeIntegralInRange<std::size_t>(0, n - 1)]);
                break;
            case 5: {  // collinear with two earlier vertices
                const glm::vec3 a =
                    mesh.positions[in.ConsumeIntegralInRange<std::size_t>(0, n - 1)];
                const glm::vec3 b =
                    mesh.positions[in.ConsumeIntegralInRange<std::size_t>(0, n - 1)];
                mesh.positions.push_back(a + (b - a) * hostile_float(in));
                break;
            }
            default:
                mesh.positions.push_back(hostile_vec3(in));
        }
    }
    const int triangles = in.ConsumeIntegralInRange(0, 64);
    for (int i = 0; i < 3 * triangles && vertices > 0; ++i)
        mesh.indices.push_back(in.ConsumeIntegralInRange<std::uint32_t>(0, vertices - 1));
    if (in.ConsumeBool())
        for (int v = 0; v < vertices; ++v) mesh.normals.push_back(hostile_vec3(in));
    if (in.ConsumeBool())
        for (int v = 0; v < vertices; ++v) {
            const float s = hostile_float(in), t = hostile_float(in);
            mesh.uvs.emplace_back(s, t);
        }
    if (in.ConsumeBool())  // vertex colors: mostly in [0, 1], sometimes hostile (refused)
        for (int v = 0; v < vertices; ++v) {
            const bool hostile = in.ConsumeIntegralInRange(0, 15) == 0;
            const float a = hostile ? hostile_float(in) : in.ConsumeProbability<float>();
            mesh.colors.emplace_back(in.ConsumeProbability<float>(), in.ConsumeProbability<float>(),
                                     in.ConsumeProbability<float>(), a);
        }
    mesh.material = in.ConsumeIntegralInRange<std::uint32_t>(0, 3);
    update_bounds(mesh);
    return mesh;
}

Material make_material(FuzzedDataProvider& in) {
    Material m;
    if (in.ConsumeBool()) return m;
    m.base_color = hostile_vec3(in);
    m.ambient = hostile_float(in);
    m.diffuse = hostile_float(in);
    m.specular = hostile_vec3(in);
    m.shininess = hostile_float(in);
    m.opacity = hostile_float(in);
    if (in.ConsumeBool()) {
        const int w = in.ConsumeIntegralInRange(1, 8), h = in.ConsumeIntegralInRange(1, 8);
        std::vector<std::uint8_t> rgba = in.ConsumeBytes<std::uint8_t>(std::size_t(w * h * 4));
        rgba.resize(std::size_t(w * h * 4), 128);
        m.base_color_texture = std::make_shared<const Texture>(w, h, rgba);
    }
    m.alpha_mode = static_cast<AlphaMode>(in.ConsumeIntegralInRange(0, 2));
    m.alpha_cutoff = hostile_float(in);
    if (in.ConsumeBool()) m.opacity_texture = m.base_color_texture;
    return m;
}

glm::mat4 make_transform(FuzzedDataProvider& in) {
    glm::mat4 m(1.0f);
    switch (in.ConsumeIntegralInRange(0, 4)) {
        case 0:
            return m;
        case 1:  // singular: a zero row or everything zero
            if (in.ConsumeBool()) return glm::mat4(0.0f);
            m[0][in.ConsumeIntegralInRange(0, 3)] = 0.0f;
            m[1][0] = m[0][0];
            m[1][1] = m[0][1];
            m[1][2] = m[0][2];
            return m;
        case 2:  // translate and scale
            m[3] = glm::vec4(hostile_vec3(in), 1.0f);
            m[0][0] = hostile_float(in);
            m[1][1] = hostile_float(in);
            m[2][2] = hostile_float(in);
            return m;
        default:  // anything, w row included
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = hostile_float(in);
            return m;
    }
}

Camera make_camera(FuzzedDataProvider& in) {
    Camera c;
    c.eye = in.ConsumeBool() ? glm::dvec3(3.0, 2.0, 5.0) : hostile_dvec3(in);
    c.target = in.ConsumeBool() ? glm::dvec3(0.0) : hostile_dvec3(in);
    c.up = in.ConsumeBool() ? glm::dvec3(0.0, 1.0, 0.0) : hostile_dvec3(in);
    c.projection =
        in.ConsumeBool() ? Camera::Projection::Perspective : Camera::Projection::Orthographic;
    c.fovy_degrees = in.ConsumeBool() ? 60.0 : hostile_double(in);
    c.ortho_height = in.ConsumeBool() ? 4.0 : hostile_double(in);
    c.near = in.ConsumeBool() ? 0.1 : hostile_double(in);
    c.far = in.ConsumeBool() ? 100.0 : hostile_double(in);
    c.reversed_z = in.ConsumeBool();
    c.infinite_far = in.ConsumeBool();
    return c;
}

RenderOptions make_options(FuzzedDataProvider& in) {
    RenderOptions o;
    o.width = in.ConsumeIntegralInRange(1, 96);
    o.height = in.ConsumeIntegralInRange(1, 96);
    if (in.ConsumeIntegralInRange(0, 31) == 0) {  // out of range: must be refused
        static constexpr int kBad[] = {0, -1, -100000, 16385, 1 << 30, INT32_MIN, INT32_MAX};
        (in.ConsumeBool() ? o.width : o.height) = in.PickValueInArray(kBad);
    }
    if (in.ConsumeIntegralInRange(0, 31) == 0)
        o.limits.max_pixels = in.ConsumeIntegral<std::uint8_t>();
    if (in.ConsumeIntegralInRange(0, 31) == 0)
        o.limits.max_triangles = in.ConsumeIntegral<std::uint8_t>();
    if (in.ConsumeBool()) o.camera = make_camera(in);
    o.shading = in.PickValueInArray(
        {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::Unlit});
    o.lighting.reflection = in.ConsumeBool() ? ReflectionModel::Phong : ReflectionModel::BlinnPhong;
    o.lighting.local_viewer = in.ConsumeBool();
    if (in.ConsumeBool()) {
        o.lighting.lights.resize(in.ConsumeIntegralInRange(0, 3));
        for (Light& light : o.lighting.lights) {
            light.type = in.ConsumeBool() ? Light::Type::Directional : Light::Type::Point;
            light.direction = hostile_vec3(in);
            light.position = hostile_vec3(in);
            light.color = hostile_vec3(in);
            light.quadratic_attenuation = hostile_float(in);
        }
    }
    o.texture_filter = in.PickValueInArray(
        {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear});
    o.interpolation =
        in.ConsumeBool() ? Interpolation::PerspectiveCorrect : Interpolation::ScreenLinear;
    o.textures = in.ConsumeBool();
    o.two_sided_lighting = in.ConsumeBool();
    o.strategy = in.PickValueInArray(
        {ShadingStrategy::Auto, ShadingStrategy::Forward, ShadingStrategy::Deferred});
    o.simd = in.ConsumeBool();
    o.cull = in.PickValueInArray({CullMode::None, CullMode::Back, CullMode::Front});
    o.front_face = in.ConsumeBool() ? FrontFace::CounterClockwise : FrontFace::Clockwise;
    o.depth_format = in.PickValueInArray({DepthFormat::D32F, DepthFormat::D24, DepthFormat::D16});
    if (in.ConsumeBool())
        o.depth_compare = in.PickValueInArray({CompareFunc::Never, CompareFunc::Less,
                                               CompareFunc::LessEqual, CompareFunc::Equal,
                                               CompareFunc::NotEqual, CompareFunc::GreaterEqual,
                                               CompareFunc::Greater, CompareFunc::Always});
    o.depth_test = in.ConsumeBool();
    o.depth_write = in.ConsumeBool();
    const int planes = in.ConsumeIntegralInRange(0, 7);  // 7: one more than supported
    for (int p = 0; p < planes; ++p)
        o.clip_planes.emplace_back(hostile_vec3(in), hostile_float(in));
    if (in.ConsumeBool()) o.background = hostile_vec3(in);
    o.color_target = in.ConsumeBool();
    o.normal_target = in.ConsumeBool();
    o.id_targets = in.ConsumeBool();
    o.coverage_counts = in.ConsumeBool();
    return o;
}

Scene make_scene(FuzzedDataProvider& in) {
    Scene scene;
    scene.name = "fuzz";
    const int meshes = in.ConsumeIntegralInRange(1, 3);
    for (int m = 0; m < meshes; ++m) scene.meshes.push_back(make_mesh(in));
    const int materials = in.ConsumeIntegralInRange(0, 3);
    for (int m = 0; m < materials; ++m) scene.materials.push_back(make_material(in));
    const int instances = in.ConsumeIntegralInRange(0, 4);
    for (int i = 0; i < instances; ++i) {
        Instance instance;
        instance.mesh = in.ConsumeIntegralInRange<std::uint32_t>(0, meshes - 1);
        instance.transform = make_transform(in);
        if (in.ConsumeBool())
            instance.shading = in.PickValueInArray(
                {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::Unlit});
        scene.instances.push_back(instance);
    }
    // Inconsistent scenes, which render() must refuse rather than read out of bounds.
    switch (in.ConsumeIntegralInRange(0, 15)) {
        case 0:
            if (!scene.instances.empty()) scene.instances[0].mesh = std::uint32_t(meshes);
            break;
        case 1:
            scene.meshes[0].indices.push_back(std::uint32_t(scene.meshes[0].positions.size()));
            scene.meshes[0].indices.push_back(0);
            scene.meshes[0].indices.push_back(0);
            break;
        case 2:
            scene.meshes[0].normals.resize(scene.meshes[0].positions.size() + 1);
            break;
        case 3:
            scene.materials.clear();
            break;
        default:
            break;
    }
    return scene;
}

void check_targets(const RenderResult& r, const Scene& scene, const RenderOptions& o) {
    const RenderTargets& t = r.targets;
    const std::size_t pixels = std::size_t(o.width) * std::size_t(o.height);
    if (t.width != o.width || t.height != o.height) fail("target size differs from the options");
    if (t.depth.size() != pixels) fail("depth target size");
    if (o.color_target && t.color.size() != pixels * 4) fail("color target size");
    if (o.normal_target && t.normal.size() != pixels) fail("normal target size");
    if (o.id_targets && (t.instance_id.size() != pixels || t.primitive_id.size() != pixels))
        fail("id target size");
    if (o.coverage_counts && (t.front_hits.size() != pixels || t.back_hits.size() != pixels))
        fail("coverage target size");
    for (float d : t.depth)
        if (!(d >= 0.0f && d <= 1.0f)) fail("depth " + std::to_string(d) + " outside [0, 1]");
    for (std::size_t i = 0; i < t.instance_id.size(); ++i) {
        const std::int32_t instance = t.instance_id[i], primitive = t.primitive_id[i];
        if (instance == -1 && primitive == -1) continue;
        if (instance < 0 || std::size_t(instance) >= scene.instances.size())
            fail("instance id " + std::to_string(instance) + " out of range");
        const Mesh& mesh = scene.meshes[scene.instances[std::size_t(instance)].mesh];
        if (primitive < 0 || std::size_t(primitive) >= mesh.triangle_count())
            fail("primitive id " + std::to_string(primitive) + " out of range");
    }
}

bool same_bytes(const auto& a, const auto& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0);
}

void check_identical(const RenderTargets& a, const RenderTargets& b, const char* what) {
    if (!same_bytes(a.color, b.color)) fail(std::string("color differs: ") + what);
    if (!same_bytes(a.depth, b.depth)) fail(std::string("depth differs: ") + what);
    if (!same_bytes(a.normal, b.normal)) fail(std::string("normals differ: ") + what);
    if (!same_bytes(a.instance_id, b.instance_id))
        fail(std::string("instance ids differ: ") + what);
    if (!same_bytes(a.primitive_id, b.primitive_id))
        fail(std::string("primitive ids differ: ") + what);
    if (!same_bytes(a.front_hits, b.front_hits) || !same_bytes(a.back_hits, b.back_hits))
        fail(std::string("coverage counts differ: ") + what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    RenderOptions options = make_options(in);
    const Scene scene = make_scene(in);
    const int threads = in.ConsumeIntegralInRange(2, 3);

    options.threads = 1;
    RenderResult reference;
    try {
        reference = render(scene, options);
    } catch (const InputError& e) {
        if (std::string(e.what()).find('\n') != std::string::npos) fail("multi-line error");
        return 0;
    }
    check_targets(reference, scene, options);

    options.threads = threads;
    check_identical(render(scene, options).targets, reference.targets, "2-3 threads vs 1");
    // A Renderer keeps its arrays from one frame to the next, over every input of the run.
    static Renderer renderer;
    check_identical(renderer.render(scene, options).targets, reference.targets,
                    "reused Renderer vs a fresh one");
    return 0;
}
