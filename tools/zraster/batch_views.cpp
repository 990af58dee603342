// See batch_views.hpp.
#include "batch_views.hpp"

#include "io/json_errors.hpp"
#include "io/json_fields.hpp"

#include <zraster/error.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

#include "camera_ranges.hpp"
#include "command_line.hpp"
#include "input_stream.hpp"

namespace zraster::cli {
namespace {

constexpr std::size_t kMaxViewsJsonBytes = std::size_t(16) << 20;

using Json = nlohmann::json;

std::string suffix(std::size_t index, std::size_t count) {
    const int digits = count <= 100 ? 2 : 3;  // at most 1000 views
    return fmt::format("_v{:0{}}", index, digits);
}

// Reads one camera of a --views-json file; errors name "FILE: camera I: field".
class CameraReader {
  public:
    CameraReader(const std::filesystem::path& file, std::size_t index, const Json& camera)
        : file_(file.string()), index_(index), camera_(camera) {
        if (!camera.is_object()) fail("", "a camera must be a JSON object");
    }

    [[noreturn]] void fail(const std::string& field, const std::string& cause) const {
        throw InputError(file_, "camera " + std::to_string(index_) +
                                    (field.empty() ? "" : ": \"" + field + "\"") + ": " + cause);
    }

    bool has(const char* field) const { return camera_.contains(field); }

    double scalar(const Json& value, const std::string& field) const {
        if (!value.is_number()) fail(field, "expected a number, got " + value.dump());
        const double x = value.get<double>();
        if (!std::isfinite(x)) fail(field, "must be finite");
        return x;
    }

    std::optional<double> optional_scalar(const char* field) const {
        if (!has(field)) return std::nullopt;
        return scalar(camera_.at(field), field);
    }

    std::vector<double> numbers(const Json& value, const std::string& field,
                                std::size_t count) const {
        if (!value.is_array() || value.size() != count)
            fail(field, "expected " + std::to_string(count) + " numbers, got " + value.dump());
        std::vector<double> out;
        for (const Json& item : value) out.push_back(scalar(item, field));
        return out;
    }

    // "X,Y,Z" as the flags take it, checked by `problem` (camera_ranges.hpp).
    std::string vec3(const char* field, std::string (*problem)(const glm::dvec3&)) const {
        const std::vector<double> v = numbers(camera_.at(field), field, 3);
        if (const std::string p = problem({v[0], v[1], v[2]}); !p.empty()) fail(field, p);
        return exact_number(v[0]) + "," + exact_number(v[1]) + "," + exact_number(v[2]);
    }

    // A number checked by `problem` (camera_ranges.hpp), if the camera has it.
    std::optional<double> checked_scalar(const char* field, std::string (*problem)(double)) const {
        const std::optional<double> x = optional_scalar(field);
        if (x)
            if (const std::string p = problem(*x); !p.empty()) fail(field, p);
        return x;
    }

    const Json& at(const char* field) const { return camera_.at(field); }

  private:
    std::string file_;
    std::size_t index_;
    const Json& camera_;
};

void read_pose_and_size(const CameraReader& r, BatchView& view, const char* needs);

// What --camera-json writes: the pinhole K and the OpenCV camera-to-world pose become
// --intrinsics and --eye/--target/--up, width and height --size, near and far the clip distances.
void read_pinhole(const CameraReader& r, BatchView& view) {
    if (r.has("convention") && r.at("convention") != "opencv")
        r.fail("convention", "only \"opencv\" is read, got " + r.at("convention").dump());
    const Json& k = r.at("K");
    if (!k.is_array() || k.size() != 3) r.fail("K", "expected a 3x3 array, got " + k.dump());
    const std::vector<double> k0 = r.numbers(k[0], "K", 3), k1 = r.numbers(k[1], "K", 3),
                              k2 = r.numbers(k[2], "K", 3);
    if (k0[1] != 0.0 || k1[0] != 0.0 || k2 != std::vector<double>{0.0, 0.0, 1.0})
        r.fail("K", "expected [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (no skew), got " + k.dump());
    if (const std::string p = intrinsics_problem({k0[0], k1[1], k0[2], k1[2]}); !p.empty())
        r.fail("K", p);
    view.intrinsics = exact_number(k0[0]) + "," + exact_number(k1[1]) + "," + exact_number(k0[2]) +
                      "," + exact_number(k1[2]);
    read_pose_and_size(r, view, "K");
}

// An OpenCV camera-to-world pose (x right, y down, z forward; the translation is the eye) as
// --eye/--target/--up, and width and height as --size.
void read_pose_and_size(const CameraReader& r, BatchView& view, const char* needs) {
    if (!r.has("camera_to_world"))
        r.fail("camera_to_world", std::string("is missing (") + needs + " needs a pose)");
    const Json& pose = r.at("camera_to_world");
    if (!pose.is_array() || pose.size() != 4)
        r.fail("camera_to_world", "expected a 4x4 array, got " + pose.dump());
    double m[4][4];
    for (std::size_t row = 0; row < 4; ++row) {
        const std::vector<double> values = r.numbers(pose[row], "camera_to_world", 4);
        for (std::size_t col = 0; col < 4; ++col) m[row][col] = values[col];
    }
    // The forward (z) and down (y) columns give the view direction and the up direction.
    if (!pose_problem({0, 0, 0}, {m[0][2], m[1][2], m[2][2]}, {m[0][1], m[1][1], m[2][1]}).empty())
        r.fail("camera_to_world",
               "the rotation's forward (z) and down (y) columns must be nonzero and not parallel");
    const double eye[3] = {m[0][3], m[1][3], m[2][3]};
    view.eye = exact_number(eye[0]) + "," + exact_number(eye[1]) + "," + exact_number(eye[2]);
    view.target = exact_number(eye[0] + m[0][2]) + "," + exact_number(eye[1] + m[1][2]) + "," +
                  exact_number(eye[2] + m[2][2]);
    view.up = exact_number(-m[0][1]) + "," + exact_number(-m[1][1]) + "," + exact_number(-m[2][1]);
    if (r.has("width") != r.has("height"))
        r.fail(r.has("width") ? "height" : "width", "is missing (width and height go together)");
    if (r.has("width")) {
        const Json& w = r.at("width");
        const Json& h = r.at("height");
        if (!w.is_number_unsigned() || !h.is_number_unsigned())
            r.fail("width",
                   "width and height must be whole numbers, got " + w.dump() + " and " + h.dump());
        view.size =
            std::to_string(w.get<std::uint64_t>()) + "x" + std::to_string(h.get<std::uint64_t>());
    }
    if (r.has("far") && r.at("far").is_null()) view.infinite_far = true;
}

// What --camera-json writes for an orthographic camera: u = su X + cu, v = sv Y + cv. The
// command's orthographic camera is centered with square pixels: others are refused.
void read_orthographic(const CameraReader& r, BatchView& view) {
    if (r.has("convention") && r.at("convention") != "opencv")
        r.fail("convention", "only \"opencv\" is read, got " + r.at("convention").dump());
    if (!r.has("pixels_per_unit")) r.fail("pixels_per_unit", "is missing (orthographic)");
    if (!r.has("principal_point")) r.fail("principal_point", "is missing (orthographic)");
    if (!r.has("width") || !r.has("height"))
        r.fail(r.has("width") ? "height" : "width", "is missing (orthographic)");
    const std::vector<double> scale = r.numbers(r.at("pixels_per_unit"), "pixels_per_unit", 2);
    const std::vector<double> center = r.numbers(r.at("principal_point"), "principal_point", 2);
    read_pose_and_size(r, view, "an orthographic camera");
    const double width = r.at("width").get<double>(), height = r.at("height").get<double>();
    if (!(scale[0] > 0.0 && scale[1] > 0.0) ||
        std::abs(scale[0] - scale[1]) > 1e-6 * std::max(scale[0], scale[1]))
        r.fail("pixels_per_unit", "expected two equal positive scales (square pixels), got " +
                                      r.at("pixels_per_unit").dump());
    if (std::abs(center[0] - 0.5 * (width - 1.0)) > 1e-6 * width ||
        std::abs(center[1] - 0.5 * (height - 1.0)) > 1e-6 * height)
        r.fail("principal_point",
               "expected the image center [(width - 1) / 2, (height - 1) / 2]"
               ", got " +
                   r.at("principal_point").dump());
    view.ortho_height = height / scale[1];
}

BatchView read_camera(const std::filesystem::path& file, std::size_t index, const Json& camera) {
    const CameraReader r(file, index, camera);
    // The fields read here and those --camera-json writes; anything else is a typo ("fov") that
    // would silently leave the default in place.
    if (const auto field = io::unknown_field(
            camera, {"eye", "target", "up", "orbit", "fovy", "near", "far", "projection", "K",
                     "camera_to_world", "width", "height", "convention", "convention_note",
                     "pixels_per_unit", "principal_point", "depth"}))
        r.fail(*field,
               "is not a camera field (eye, target, up, orbit, fovy, near, far, K, "
               "camera_to_world, projection: docs/batch.md)");
    BatchView view;
    // ("projection": "orthographic" is what --camera-json writes for --ortho.)
    if (r.has("projection") && r.at("projection") != "orthographic" &&
        r.at("projection") != "perspective")
        r.fail("projection",
               "expected \"perspective\" or \"orthographic\", got " + r.at("projection").dump());
    const bool orthographic = r.has("projection") && r.at("projection") == "orthographic";
    const int kinds = int(r.has("eye")) + int(r.has("orbit")) + int(r.has("K")) + int(orthographic);
    if (kinds != 1)
        r.fail("", kinds == 0 ? "needs \"eye\" and \"target\", \"orbit\", \"K\" and "
                                "\"camera_to_world\", or an orthographic camera as "
                                "--camera-json writes it"
                              : "give one of \"eye\", \"orbit\", \"K\" and an orthographic "
                                "projection");
    if (r.has("eye")) {
        if (!r.has("target")) r.fail("target", "is missing (\"eye\" needs it)");
        view.eye = r.vec3("eye", position_problem);
        view.target = r.vec3("target", position_problem);
        if (r.has("up")) view.up = r.vec3("up", direction_problem);
        const std::vector<double> e = r.numbers(r.at("eye"), "eye", 3),
                                  t = r.numbers(r.at("target"), "target", 3),
                                  u = r.has("up") ? r.numbers(r.at("up"), "up", 3)
                                                  : std::vector<double>{0.0, 1.0, 0.0};
        if (const std::string p =
                pose_problem({e[0], e[1], e[2]}, {t[0], t[1], t[2]}, {u[0], u[1], u[2]});
            !p.empty())
            r.fail(r.has("up") ? "up" : "target", p);
    } else if (r.has("orbit")) {
        const std::vector<double> o = r.numbers(r.at("orbit"), "orbit", 3);
        if (const std::string p = orbit_problem({o[0], o[1], o[2]}); !p.empty()) r.fail("orbit", p);
        view.orbit = exact_number(o[0]) + "," + exact_number(o[1]) + "," + exact_number(o[2]);
    } else if (orthographic) {
        read_orthographic(r, view);
    } else {
        read_pinhole(r, view);
    }
    if (!r.has("K") && !orthographic) view.fovy = r.checked_scalar("fovy", fovy_problem);
    view.near = r.checked_scalar("near", distance_problem);
    if (!view.infinite_far) view.far = r.checked_scalar("far", distance_problem);
    if (view.near && view.far && !(*view.near < *view.far)) r.fail("near", "must be below \"far\"");
    return view;
}

}  // namespace

std::vector<BatchView> single_view() {
    return {BatchView{}};
}

std::vector<BatchView> orbit_views(int count, double elevation, std::optional<double> fovy) {
    if (count < 1 || count > 1000) throw InputError("--views", "must be in 1..1000");
    if (!(elevation >= -90.0 && elevation <= 90.0))
        throw InputError("--elevation", "must be in -90..90 degrees");
    const double half_fovy = fovy.value_or(60.0) * std::numbers::pi / 360.0;
    if (!(std::sin(half_fovy) > 0.0))
        throw InputError("--fovy", "must be in (0, 180) degrees for --views");
    const double distance = 1.0 / std::sin(half_fovy);
    std::vector<BatchView> views;
    for (int i = 0; i < count; ++i) {
        BatchView view;
        view.suffix = suffix(std::size_t(i), std::size_t(count));
        view.orbit = exact_number(360.0 * i / count) + "," + exact_number(elevation) + "," +
                     exact_number(distance);
        views.push_back(view);
    }
    return views;
}

std::vector<BatchView> read_views_json(const std::filesystem::path& path) {
    // At most 16 MiB (1000 cameras take far less): a device such as /dev/zero is not read for ever.
    const std::unique_ptr<std::istream> in =
        open_input_stream(path, "--views-json " + path.string());
    std::string text(kMaxViewsJsonBytes + 1, '\0');
    in->read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in->gcount()));
    if (text.size() > kMaxViewsJsonBytes)
        throw InputError(path.string(),
                         "longer than 16 MiB: more than the 1000 cameras a batch takes");
    Json document;
    try {
        document = Json::parse(text);
    } catch (const Json::exception& e) {
        throw InputError(path.string(), "not valid JSON: " + io::json_error_text(e));
    }
    if (document.is_object()) document = Json::array({document});
    if (!document.is_array() || document.empty())
        throw InputError(path.string(), "expected a camera object or a non-empty array of them");
    if (document.size() > 1000) throw InputError(path.string(), "more than 1000 cameras");
    std::vector<BatchView> views;
    for (std::size_t i = 0; i < document.size(); ++i) {
        views.push_back(read_camera(path, i, document[i]));
        views.back().suffix = suffix(i, document.size());
    }
    return views;
}

RenderArguments with_view(const RenderArguments& base, const BatchView& view) {
    RenderArguments a = base;
    if (!view.orbit.empty()) a.orbit = view.orbit;
    if (!view.eye.empty()) a.eye = view.eye;
    if (!view.target.empty()) a.target = view.target;
    if (!view.up.empty()) a.up = view.up;
    if (!view.intrinsics.empty()) a.depth_camera.intrinsics = view.intrinsics;
    if (!view.size.empty()) a.size = view.size;
    if (view.fovy) a.fovy = view.fovy;
    if (view.near) a.near = view.near;
    if (view.far) a.far = view.far;
    if (view.infinite_far) a.infinite_far = true;
    if (view.ortho_height) {
        a.ortho = true;
        a.ortho_height = view.ortho_height;
    }
    return a;
}

}  // namespace zraster::cli
