#include "io/worker_message.hpp"

#include <zraster/error.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace zraster::io {

static_assert(std::endian::native == std::endian::little, "the worker format is little-endian");

namespace {

constexpr char kMagic[4] = {'Z', 'R', 'W', 'M'};
constexpr std::uint32_t kNoTexture = ~0u;
constexpr std::uint8_t kNoShading = 255;
// A material's fixed part: name length, 10 floats, alpha mode, alpha cutoff, two textures.
constexpr std::size_t kMinMaterialBytes = 4 + 40 + 1 + 4 + 8;

class Writer {
  public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const char*>(&value);
        out_.append(p, sizeof(T));
    }
    void put_string(const std::string& s) {
        const std::size_t n = std::min(s.size(), kMaxWorkerString);
        put(static_cast<std::uint32_t>(n));
        out_.append(s.data(), n);
    }
    template <typename T>
    void put_array(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put(static_cast<std::uint64_t>(values.size()));
        if (!values.empty())
            out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void put_bytes(std::span<const std::uint8_t> bytes) {
        if (!bytes.empty()) out_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }
    std::string finish(WorkerMessageKind kind) {
        std::string message(kMagic, sizeof kMagic);
        Writer header;
        header.put(kWorkerMessageVersion);
        header.put(static_cast<std::uint32_t>(kind));
        header.put(std::uint32_t{0});
        header.put(static_cast<std::uint64_t>(out_.size()));
        message += header.out_;
        message += out_;
        return message;
    }

  private:
    std::string out_;
};

// Thrown by Reader on anything out of bounds or out of range; becomes an InputError.
struct Malformed {
    std::string what;
};

class Reader {
  public:
    explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    template <typename T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T), "a field");
        T value;
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return value;
    }
    std::string get_string(const char* what) {
        const auto n = get<std::uint32_t>();
        if (n > kMaxWorkerString) throw Malformed{std::string(what) + " longer than the limit"};
        need(n, what);
        std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
        pos_ += n;
        return s;
    }
    // A u64 element count followed by its elements, checked against the bytes left before the
    // vector is allocated.
    template <typename T>
    std::vector<T> get_array(const char* what) {
        const auto n = get<std::uint64_t>();
        if (n > remaining() / sizeof(T))
            throw Malformed{std::string(what) + ": " + std::to_string(n) +
                            " elements do not fit in the message"};
        std::vector<T> values(static_cast<std::size_t>(n));
        if (n != 0) std::memcpy(values.data(), bytes_.data() + pos_, values.size() * sizeof(T));
        pos_ += values.size() * sizeof(T);
        return values;
    }
    // A u32 count of records of at least min_bytes each.
    std::uint32_t get_count(std::size_t min_bytes, const char* what) {
        const auto n = get<std::uint32_t>();
        if (n > remaining() / min_bytes)
            throw Malformed{std::string(what) + ": " + std::to_string(n) +
                            " records do not fit in the message"};
        return n;
    }
    std::span<const std::uint8_t> get_bytes(std::size_t n, const char* what) {
        need(n, what);
        const auto s = bytes_.subspan(pos_, n);
        pos_ += n;
        return s;
    }
    std::size_t remaining() const { return bytes_.size() - pos_; }

  private:
    void need(std::size_t n, const char* what) const {
        if (n > remaining()) throw Malformed{std::string("truncated in ") + what};
    }
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_ = 0;
};

bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check(bool ok, const std::string& what) {
    if (!ok) throw Malformed{what};
}

// A field name as LimitExceeded::limit() gives it: what a front end looks up to name its flag.
bool valid_limit_name(const std::string& name) {
    if (name.empty() || name.size() > 64) return false;
    for (const char c : name)
        if (!((c >= 'a' && c <= 'z') || c == '_')) return false;
    return true;
}

LoadedScene decode_scene(Reader& in, const LoadOptions& options) {
    LoadedScene loaded;
    Scene& scene = loaded.scene;
    scene.materials.clear();
    scene.name = in.get_string("the source name");
    const std::uint32_t warnings = in.get_count(4, "warnings");
    for (std::uint32_t i = 0; i < warnings; ++i)
        loaded.warnings.push_back(InputError("", in.get_string("a warning")).cause());
    const std::uint32_t files_read = in.get_count(4, "files read");
    for (std::uint32_t i = 0; i < files_read; ++i) {
        std::string file = in.get_string("a file read");
        // (Used only to keep outputs off them: a hostile child can at most refuse an output.)
        check(file.starts_with('/') && file.find('\0') == std::string::npos,
              "file read " + std::to_string(i) + " is not an absolute path");
        loaded.files_read.emplace_back(std::move(file));
    }

    const std::uint32_t texture_count = in.get_count(8, "textures");
    std::vector<std::shared_ptr<const Texture>> textures;
    for (std::uint32_t i = 0; i < texture_count; ++i) {
        const auto w = in.get<std::uint32_t>(), h = in.get<std::uint32_t>();
        check(w >= 1 && h >= 1 && w <= std::uint32_t(kMaxWorkerTextureSide) &&
                  h <= std::uint32_t(kMaxWorkerTextureSide),
              "texture " + std::to_string(i) + " of size " + std::to_string(w) + "x" +
                  std::to_string(h));
        const auto rgba = in.get_bytes(std::size_t(w) * h * 4, "a texture");
        textures.push_back(std::make_shared<const Texture>(int(w), int(h), rgba));
    }

    const std::uint32_t material_count = in.get_count(kMinMaterialBytes, "materials");
    check(material_count >= 1, "no materials");
    for (std::uint32_t i = 0; i < material_count; ++i) {
        Material m;
        const std::string label = "material " + std::to_string(i);
        m.name = in.get_string("a material name");
        m.base_color = in.get<glm::vec3>();
        m.ambient = in.get<float>();
        m.diffuse = in.get<float>();
        m.specular = in.get<glm::vec3>();
        m.shininess = in.get<float>();
        m.opacity = in.get<float>();
        check(finite3(m.base_color) && std::isfinite(m.ambient) && std::isfinite(m.diffuse) &&
                  finite3(m.specular) && std::isfinite(m.shininess) && std::isfinite(m.opacity),
              label + " has non-finite values");
        check(m.opacity >= 0.0f && m.opacity <= 1.0f, label + ": opacity outside [0, 1]");
        const auto mode = in.get<std::uint8_t>();
        check(mode <= std::uint8_t(AlphaMode::Blend),
              label + ": unknown alpha mode " + std::to_string(mode));
        m.alpha_mode = static_cast<AlphaMode>(mode);
        m.alpha_cutoff = in.get<float>();
        check(m.alpha_cutoff >= 0.0f && m.alpha_cutoff <= 1.0f,  // false for NaN
              label + ": alpha cutoff not in [0, 1]");
        const auto sides = in.get<std::uint8_t>();
        check(sides <= 1, label + ": double_sided is " + std::to_string(sides) + ", not 0 or 1");
        m.double_sided = sides == 1;
        const auto texture = [&](const char* what) -> std::shared_ptr<const Texture> {
            const auto index = in.get<std::uint32_t>();
            if (index == kNoTexture) return nullptr;
            check(index < textures.size(), label + " names a missing " + what);
            return textures[index];
        };
        m.base_color_texture = texture("texture");
        m.opacity_texture = texture("opacity texture");
        scene.materials.push_back(std::move(m));
    }

    const std::uint32_t mesh_count = in.get_count(48, "meshes");
    for (std::uint32_t i = 0; i < mesh_count; ++i) {
        Mesh mesh;
        const std::string label = "mesh " + std::to_string(i);
        mesh.name = in.get_string("a mesh name");
        mesh.material = in.get<std::uint32_t>();
        check(mesh.material < scene.materials.size(), label + " names a missing material");
        mesh.positions = in.get_array<glm::vec3>("positions");
        mesh.normals = in.get_array<glm::vec3>("normals");
        mesh.uvs = in.get_array<glm::vec2>("uvs");
        mesh.colors = in.get_array<glm::vec4>("colors");
        mesh.indices = in.get_array<std::uint32_t>("indices");
        const std::size_t n = mesh.positions.size();
        check(n <= 0xffffffffu, label + " has more than 2^32 - 1 vertices");
        // load_scene computes normals when a file has none: always one per position.
        check(mesh.normals.size() == n, label + ": normals not one per position");
        check(mesh.uvs.empty() || mesh.uvs.size() == n, label + ": uvs not one per position");
        check(mesh.colors.empty() || mesh.colors.size() == n,
              label + ": colors not one per position");
        check(!mesh.indices.empty() && mesh.indices.size() % 3 == 0,
              label + ": index count not a positive multiple of 3");
        for (const std::uint32_t index : mesh.indices)
            check(index < n, label + ": index " + std::to_string(index) + " out of range");
        for (const glm::vec3& p : mesh.positions)
            check(finite3(p), label + ": non-finite position");
        for (const glm::vec3& normal : mesh.normals)
            check(finite3(normal) && std::fabs(glm::length(normal) - 1.0f) <= 1e-3f,
                  label + ": a normal is not finite and of unit length");
        for (const glm::vec2& uv : mesh.uvs)
            check(std::isfinite(uv.x) && std::isfinite(uv.y), label + ": non-finite uv");
        for (const glm::vec4& c : mesh.colors)
            check(c.x >= 0.0f && c.x <= 1.0f && c.y >= 0.0f && c.y <= 1.0f && c.z >= 0.0f &&
                      c.z <= 1.0f && c.w >= 0.0f && c.w <= 1.0f,
                  label + ": a vertex color is outside [0, 1]");
        update_bounds(mesh);
        scene.meshes.push_back(std::move(mesh));
    }

    const std::uint32_t instance_count = in.get_count(73, "instances");
    check(instance_count >= 1, "no instances");
    std::size_t triangles = 0;
    for (std::uint32_t i = 0; i < instance_count; ++i) {
        Instance instance;
        const std::string label = "instance " + std::to_string(i);
        instance.mesh = in.get<std::uint32_t>();
        check(instance.mesh < scene.meshes.size(), label + " names a missing mesh");
        instance.transform = in.get<glm::mat4>();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                check(std::isfinite(instance.transform[c][r]), label + ": non-finite transform");
        const auto shading = in.get<std::uint8_t>();
        check(shading == kNoShading || shading <= std::uint8_t(ShadingMode::Unlit),
              label + ": unknown shading mode " + std::to_string(shading));
        if (shading != kNoShading) instance.shading = static_cast<ShadingMode>(shading);
        instance.name = in.get_string("an instance name");
        const Mesh& mesh = scene.meshes[instance.mesh];
        const Bounds3f box = mesh.bounds.transformed(instance.transform);
        check(finite3(box.lo) && finite3(box.hi), label + ": non-finite world positions");
        triangles += mesh.triangle_count();
        check(triangles <= options.max_triangles,
              "more triangles than the limit (" + std::to_string(options.max_triangles) + ")");
        scene.instances.push_back(std::move(instance));
    }
    check(in.remaining() == 0, std::to_string(in.remaining()) + " bytes after the scene");
    return loaded;
}

}  // namespace

std::string encode_scene_message(const LoadedScene& loaded) {
    const Scene& scene = loaded.scene;
    Writer out;
    out.put_string(scene.name);
    out.put(static_cast<std::uint32_t>(loaded.warnings.size()));
    for (const std::string& w : loaded.warnings) out.put_string(w);
    out.put(static_cast<std::uint32_t>(loaded.files_read.size()));
    for (const std::filesystem::path& f : loaded.files_read) out.put_string(f.string());

    std::map<const Texture*, std::uint32_t> texture_index;
    std::vector<const Texture*> textures;
    for (const Material& m : scene.materials)
        for (const Texture* t : {m.base_color_texture.get(), m.opacity_texture.get()})
            if (t != nullptr && texture_index.emplace(t, std::uint32_t(textures.size())).second)
                textures.push_back(t);
    out.put(static_cast<std::uint32_t>(textures.size()));
    for (const Texture* t : textures) {
        out.put(static_cast<std::uint32_t>(t->width()));
        out.put(static_cast<std::uint32_t>(t->height()));
        out.put_bytes(t->level_rgba(0));
    }

    out.put(static_cast<std::uint32_t>(scene.materials.size()));
    for (const Material& m : scene.materials) {
        out.put_string(m.name);
        out.put(m.base_color);
        out.put(m.ambient);
        out.put(m.diffuse);
        out.put(m.specular);
        out.put(m.shininess);
        out.put(m.opacity);
        out.put(static_cast<std::uint8_t>(m.alpha_mode));
        out.put(m.alpha_cutoff);
        out.put(static_cast<std::uint8_t>(m.double_sided ? 1 : 0));
        out.put(m.base_color_texture ? texture_index.at(m.base_color_texture.get()) : kNoTexture);
        out.put(m.opacity_texture ? texture_index.at(m.opacity_texture.get()) : kNoTexture);
    }

    out.put(static_cast<std::uint32_t>(scene.meshes.size()));
    for (const Mesh& mesh : scene.meshes) {
        out.put_string(mesh.name);
        out.put(mesh.material);
        out.put_array(mesh.positions);
        out.put_array(mesh.normals);
        out.put_array(mesh.uvs);
        out.put_array(mesh.colors);
        out.put_array(mesh.indices);
    }

    out.put(static_cast<std::uint32_t>(scene.instances.size()));
    for (const Instance& instance : scene.instances) {
        out.put(instance.mesh);
        out.put(instance.transform);
        out.put(instance.shading ? static_cast<std::uint8_t>(*instance.shading) : kNoShading);
        out.put_string(instance.name);
    }
    return out.finish(WorkerMessageKind::Scene);
}

std::string encode_error_message(WorkerMessageKind kind, const std::string& text) {
    Writer out;
    if (kind != WorkerMessageKind::OutOfMemory) out.put_string(text);
    return out.finish(kind);
}

std::string encode_limit_message(const std::string& limit, const std::string& cause) {
    Writer out;
    out.put_string(limit);
    out.put_string(cause);
    return out.finish(WorkerMessageKind::LimitExceeded);
}

std::uint64_t worker_payload_bytes(std::span<const std::uint8_t> header, const std::string& file) {
    const auto invalid = [&](const std::string& why) {
        return InputError(file, "the importer process sent an invalid result: " + why);
    };
    if (header.size() < kWorkerHeaderBytes) throw invalid("truncated header");
    if (std::memcmp(header.data(), kMagic, sizeof kMagic) != 0) throw invalid("bad magic");
    Reader in(header.subspan(sizeof kMagic, kWorkerHeaderBytes - sizeof kMagic));
    const auto version = in.get<std::uint32_t>();
    if (version != kWorkerMessageVersion)
        throw invalid("format version " + std::to_string(version) + ", expected " +
                      std::to_string(kWorkerMessageVersion));
    const auto kind = in.get<std::uint32_t>();
    if (kind < 1 || kind > 5) throw invalid("unknown message kind " + std::to_string(kind));
    if (in.get<std::uint32_t>() != 0) throw invalid("reserved header field not 0");
    return in.get<std::uint64_t>();
}

LoadedScene decode_worker_message(std::span<const std::uint8_t> message, const std::string& file,
                                  const LoadOptions& options) {
    const std::uint64_t payload = worker_payload_bytes(message, file);
    const auto invalid = [&](const std::string& why) {
        return InputError(file, "the importer process sent an invalid result: " + why);
    };
    if (payload != message.size() - kWorkerHeaderBytes)
        throw invalid("payload of " + std::to_string(message.size() - kWorkerHeaderBytes) +
                      " bytes, the header says " + std::to_string(payload));
    std::uint32_t kind = 0;
    std::memcpy(&kind, message.data() + 8, sizeof kind);
    Reader in(message.subspan(kWorkerHeaderBytes));
    try {
        switch (static_cast<WorkerMessageKind>(kind)) {
            case WorkerMessageKind::Scene: {
                return decode_scene(in, options);
            }
            case WorkerMessageKind::InputError: {
                std::string cause = in.get_string("the error message");
                check(in.remaining() == 0, "bytes after the error message");
                if (cause.empty()) cause = "(no cause given)";
                throw InputError(file, cause);
            }
            case WorkerMessageKind::LimitExceeded: {
                const std::string limit = in.get_string("the limit's name");
                std::string cause = in.get_string("the error message");
                check(in.remaining() == 0, "bytes after the error message");
                check(valid_limit_name(limit), "a limit name that is not a LoadOptions field");
                if (cause.empty()) cause = "(no cause given)";
                throw LimitExceeded(file, limit, cause);
            }
            case WorkerMessageKind::InternalError: {
                const std::string what = in.get_string("the error message");
                check(in.remaining() == 0, "bytes after the error message");
                throw std::runtime_error("in the importer process: " +
                                         InputError("", what).cause());
            }
            case WorkerMessageKind::OutOfMemory:
                check(in.remaining() == 0, "bytes after the out-of-memory message");
                throw InputError(file, "the importer ran out of memory");
        }
    } catch (const Malformed& m) {
        throw invalid(m.what);
    }
    throw invalid("unknown message kind");
}

}  // namespace zraster::io
