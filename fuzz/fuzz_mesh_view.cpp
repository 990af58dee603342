// libFuzzer target: the zero-copy entry point, Renderer::render(const SceneView&, options,
// const TargetViews&), fed views the fuzzer lays over buffers it owns: random offsets, counts and
// strides (tightly packed, interleaved, shorter than an element, unaligned), null pointers, 16-
// and 32-bit indices (some past the vertices, some misaligned), bounds set, empty or unset,
// materials and instances naming what exists or not, and targets of any subset, pitch (packed,
// padded, shorter than a row, not a multiple of 4) and size (the options' or not), up to 48x48.
//
// One input in four is hostile (any of the above); the others break no rule, so that most
// inputs are drawn. Every view the fuzzer builds stays inside its buffers whenever its stride
// and pitch are valid, so the renderer may read and write all of it; an invalid one must be
// refused before anything is read. Oracles besides the sanitizers: render() returns or throws
// an InputError, never anything else; a row's padding (the bytes between its end and the next
// row) is never written; and a Renderer reused from earlier inputs gives the one-shot image.
#include <zraster/error.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace zraster;

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "zraster fuzz invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

constexpr std::size_t kFloats = 2048;  // the vertex buffer, in floats
constexpr std::size_t kIndexBytes = 1024;
constexpr int kMaxSide = 48;
constexpr std::uint8_t kSentinel = 0x5A;

float coordinate(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange(0, 7)) {
        case 0:
            return in.ConsumeFloatingPoint<float>();  // anything, NaN and infinities included
        case 1:
            return in.PickValueInArray({0.0f, -0.0f, 1e30f, -1e30f, 1e-40f});
        default:
            return in.ConsumeFloatingPointInRange(-2.0f, 2.0f);
    }
}

// The fuzzer's choices, and whether this input may break the rules: a hostile input picks
// invalid strides, pitches, counts and pointers among valid ones; a friendly one (three in
// four) only valid ones, so that most of them are drawn.
struct Choice {
    FuzzedDataProvider& in;
    bool hostile;
    // True one time in `n`, in a hostile input only.
    bool fault(int n) { return hostile && in.ConsumeIntegralInRange(0, n - 1) == 0; }
};

// A stride for elements of `element` bytes: packed (0 or exact), interleaved; and when hostile,
// too short, odd, or so large the elements leave the buffer or the address space.
std::size_t pick_stride(Choice& c, std::size_t element) {
    FuzzedDataProvider& in = c.in;
    switch (in.ConsumeIntegralInRange(0, c.hostile ? 6 : 2)) {
        case 0:
            return 0;
        case 1:
            return element;
        case 2:
            return element + 4 * in.ConsumeIntegralInRange<std::size_t>(1, 8);  // interleaved
        case 3:
            return in.ConsumeIntegralInRange<std::size_t>(1, element - 1);  // too short
        case 4:
            return element + in.ConsumeIntegralInRange<std::size_t>(1, 3);  // floats unaligned
        case 5:
            return in.ConsumeIntegralInRange<std::size_t>(0, 64);
        default:
            return in.ConsumeBool() ? std::numeric_limits<std::size_t>::max() / 3 : 1u << 20;
    }
}

// An attribute view over the vertex buffer: `count` elements from a random offset, the count
// cut so that every element lies inside the buffer when the stride is valid.
AttributeView pick_attribute(Choice& c, const std::vector<float>& floats, std::size_t element,
                             std::size_t count) {
    FuzzedDataProvider& in = c.in;
    AttributeView a;
    a.stride = pick_stride(c, element);
    a.count = count;
    if (count == 0) {
        a.data = in.ConsumeBool() ? floats.data() : nullptr;
        return a;
    }
    if (c.fault(8)) return a;  // null with elements
    const std::size_t bytes = floats.size() * sizeof(float);
    const std::size_t offset = in.ConsumeIntegralInRange<std::size_t>(0, bytes / 2);
    const std::size_t start = c.fault(8) ? offset | 1 : offset & ~std::size_t{3};
    const std::size_t stride = std::max(a.stride == 0 ? element : a.stride, element);
    // Elements that fit: start + (n - 1) * stride + element <= bytes. A stride so large that
    // five elements pass the end of the address space is left with its count: refused.
    const std::size_t fit = start + element > bytes ? 0 : (bytes - start - element) / stride + 1;
    const bool wraps = stride > std::numeric_limits<std::size_t>::max() / 4 && count >= 5;
    if (!wraps) a.count = std::min(count, fit);
    a.data =
        reinterpret_cast<const float*>(reinterpret_cast<const std::byte*>(floats.data()) + start);
    return a;
}

// Index buffers of both sizes: values below `vertices`, and when hostile some past them.
struct IndexBuffers {
    std::vector<std::uint16_t> small;
    std::vector<std::uint32_t> large;

    IndexBuffers(Choice& c, std::size_t vertices)
        : small(kIndexBytes / 2 + 1), large(kIndexBytes / 4 + 1) {
        const auto last = static_cast<std::uint32_t>(std::max<std::size_t>(vertices, 1) - 1);
        const auto value = [&] {
            return c.fault(16) ? c.in.ConsumeIntegral<std::uint32_t>()
                               : c.in.ConsumeIntegralInRange<std::uint32_t>(0, last);
        };
        for (std::uint16_t& i : small) i = static_cast<std::uint16_t>(value());
        for (std::uint32_t& i : large) i = value();
    }
};

IndexView pick_indices(Choice& c, const IndexBuffers& buffers) {
    FuzzedDataProvider& in = c.in;
    IndexView v;
    v.type = in.ConsumeBool() ? IndexType::UInt16 : IndexType::UInt32;
    const bool small = v.type == IndexType::UInt16;
    if (c.fault(16)) v.type = static_cast<IndexType>(2 + in.ConsumeIntegral<std::uint8_t>() % 250);
    const std::size_t capacity = small ? buffers.small.size() - 1 : buffers.large.size() - 1;
    const std::size_t first = in.ConsumeIntegralInRange<std::size_t>(0, capacity / 4);
    v.count = in.ConsumeIntegralInRange<std::size_t>(0, capacity - first);
    const auto* base = small ? static_cast<const void*>(buffers.small.data() + first)
                             : static_cast<const void*>(buffers.large.data() + first);
    v.data = base;
    if (c.fault(16)) v.data = reinterpret_cast<const std::byte*>(base) + 1;  // misaligned
    if (v.count > 0 && c.fault(16)) v.data = nullptr;
    return v;
}

// A caller target: `element` bytes a pixel, a random pitch (packed, padded, too short,
// misaligned), in a buffer whose padding holds a sentinel. Null when not wanted.
struct Target {
    std::vector<std::byte> bytes;
    std::size_t pitch = 0, row = 0;
    int height = 0;
    bool wanted = false;

    void pick(Choice& c, int width, int h, std::size_t element) {
        FuzzedDataProvider& in = c.in;
        wanted = in.ConsumeBool();
        if (!wanted) return;
        row = std::size_t(width) * element;
        height = h;
        switch (in.ConsumeIntegralInRange(0, c.hostile ? 3 : 1)) {
            case 0:
                pitch = 0;
                break;
            case 1:
                pitch = row + 4 * in.ConsumeIntegralInRange<std::size_t>(0, 8);
                break;
            case 2:
                pitch =
                    row - std::min<std::size_t>(row, in.ConsumeIntegralInRange<std::size_t>(1, 8));
                break;
            default:
                pitch = row + in.ConsumeIntegralInRange<std::size_t>(1, 3);  // not a multiple of 4
        }
        const std::size_t resolved = pitch == 0 ? row : std::max(pitch, row);
        bytes.assign(resolved * std::size_t(std::max(h, 1)) + 16, std::byte{kSentinel});
    }
    template <class T>
    T* data() {
        return wanted ? reinterpret_cast<T*>(bytes.data()) : nullptr;
    }
    // Padding and the bytes past the last row are untouched.
    void check(const char* name) const {
        if (!wanted) return;
        const std::size_t resolved = pitch == 0 ? row : pitch;
        if (resolved < row) return;  // refused: nothing was written anywhere
        for (int y = 0; y < height; ++y)
            for (std::size_t k = row; k < resolved; ++k)
                if (bytes[resolved * std::size_t(y) + k] != std::byte{kSentinel})
                    fail(std::string(name) + ": a row's padding was written");
        for (std::size_t k = resolved * std::size_t(height); k < bytes.size(); ++k)
            if (bytes[k] != std::byte{kSentinel})
                fail(std::string(name) + ": written past the end");
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    Choice c{in, in.ConsumeIntegralInRange(0, 3) == 0};
    std::vector<float> floats(kFloats);
    for (float& f : floats) f = coordinate(in);
    const std::size_t vertex_range = in.ConsumeIntegralInRange<std::size_t>(1, 80);
    const IndexBuffers index_buffers(c, vertex_range);

    std::vector<Material> materials(in.ConsumeIntegralInRange<std::size_t>(c.hostile ? 0 : 1, 2));
    std::vector<MeshView> meshes(in.ConsumeIntegralInRange<std::size_t>(0, 3));
    for (MeshView& mesh : meshes) {
        // (Friendly views always fit: 80 vertices of at most 44 bytes from the buffer's middle.)
        const std::size_t count =
            c.hostile ? in.ConsumeIntegralInRange<std::size_t>(0, vertex_range) : vertex_range;
        mesh.positions = pick_attribute(c, floats, 12, count);
        const std::size_t n = mesh.positions.count;
        // Normals, uvs and colors: none or one per position, or when hostile any count.
        const auto other = [&] {
            if (c.fault(4)) return in.ConsumeIntegralInRange<std::size_t>(0, vertex_range);
            return in.ConsumeBool() ? n : 0;
        };
        mesh.normals = pick_attribute(c, floats, 12, other());
        mesh.uvs = pick_attribute(c, floats, 8, other());
        mesh.colors = pick_attribute(c, floats, 16, other());
        mesh.indices = pick_indices(c, index_buffers);
        mesh.material = in.ConsumeIntegralInRange<std::uint32_t>(
            0, std::uint32_t(materials.size() + (c.hostile ? 1 : 0)) - (materials.empty() ? 0 : 1));
        switch (in.ConsumeIntegralInRange(0, 2)) {
            case 0:
                break;
            case 1:
                mesh.bounds = Bounds3f{};
                break;
            default:
                mesh.bounds = Bounds3f{glm::vec3(coordinate(in), coordinate(in), coordinate(in)),
                                       glm::vec3(coordinate(in), coordinate(in), coordinate(in))};
        }
        mesh.name = "fuzz";
    }
    std::vector<InstanceView> instances(in.ConsumeIntegralInRange<std::size_t>(0, 4));
    if (meshes.empty() && !c.hostile) instances.clear();
    for (InstanceView& instance : instances) {
        const std::size_t last = meshes.size() - (c.hostile || meshes.empty() ? 0 : 1);
        instance.mesh = in.ConsumeIntegralInRange<std::uint32_t>(0, std::uint32_t(last));
        if (in.ConsumeBool())
            instance.transform = glm::translate(
                glm::mat4(1.0f), glm::vec3(coordinate(in), coordinate(in), coordinate(in)));
        if (in.ConsumeBool()) instance.shading = ShadingMode::Gouraud;
    }

    RenderOptions options;
    options.width = in.ConsumeIntegralInRange(1, kMaxSide);
    options.height = in.ConsumeIntegralInRange(1, kMaxSide);
    options.threads = in.ConsumeIntegralInRange(1, 2);
    options.simd = in.ConsumeBool();
    options.occlusion_cull = in.ConsumeBool();
    options.static_meshes = in.ConsumeBool();
    options.depth_format =
        in.PickValueInArray({DepthFormat::D32F, DepthFormat::D24, DepthFormat::D16});
    options.edges =
        in.PickValueInArray({RenderOptions::Edges::None, RenderOptions::Edges::Wireframe,
                             RenderOptions::Edges::HiddenLine});
    if (in.ConsumeBool()) {
        Camera camera;
        camera.eye = {1.0, 1.5, 4.0};
        options.camera = camera;
    }

    int width = options.width, height = options.height;
    if (c.fault(16)) width = in.ConsumeIntegralInRange(0, kMaxSide);
    Target color, depth, normal, instance_id, primitive_id, front, back;
    color.pick(c, width, height, 4);
    depth.pick(c, width, height, 4);
    normal.pick(c, width, height, 12);
    instance_id.pick(c, width, height, 4);
    primitive_id.pick(c, width, height, 4);
    front.pick(c, width, height, 4);
    back.pick(c, width, height, 4);
    TargetViews targets;
    targets.width = width;
    targets.height = height;
    targets.color = color.data<std::uint8_t>();
    targets.color_pitch = color.pitch;
    targets.depth = depth.data<float>();
    targets.depth_pitch = depth.pitch;
    targets.normal = normal.data<glm::vec3>();
    targets.normal_pitch = normal.pitch;
    targets.instance_id = instance_id.data<std::int32_t>();
    targets.instance_id_pitch = instance_id.pitch;
    targets.primitive_id = primitive_id.data<std::int32_t>();
    targets.primitive_id_pitch = primitive_id.pitch;
    targets.front_hits = front.data<std::uint32_t>();
    targets.front_hits_pitch = front.pitch;
    targets.back_hits = back.data<std::uint32_t>();
    targets.back_hits_pitch = back.pitch;

    const SceneView scene{meshes, materials, instances};
    bool refused = false;
    try {
        render(scene, options, targets);
    } catch (const InputError& e) {
        refused = true;
        if (std::strchr(e.what(), '\n') != nullptr) fail("InputError message of several lines");
    }
    for (const Target* t : {&color, &depth, &normal, &instance_id, &primitive_id, &front, &back})
        t->check("target");
    if (refused || !color.wanted) return 0;

    // A Renderer kept across inputs draws the same color image.
    static Renderer kept;
    const std::vector<std::byte> once = color.bytes;
    try {
        kept.render(scene, options, targets);
    } catch (const InputError&) {
        fail("a kept Renderer refused what the one-shot render drew");
    }
    if (color.bytes != once) fail("a kept Renderer drew another image");
    return 0;
}
