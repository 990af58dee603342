// Line clipping against the view volume in homogeneous clip space, before the perspective divide
// (Blinn & Newell 1978, "Clipping using homogeneous coordinates", SIGGRAPH '78; the parametric
// method is Liang & Barsky's, done on boundary coordinates).
//
// What: for each of the six planes a "boundary coordinate" (w + x, w - x, w + y, w - y, w - z, and
// w + z or z for the near plane) is >= 0 inside and LINEAR along the clip-space segment, because
// the clip-space segment is the image of the eye-space segment under a linear map. Their signs
// give a 6-bit outcode per endpoint (the ClipPlaneBit bits of clip.hpp) for trivial accept and
// reject; for every plane the endpoints are on different sides of, the crossing is at
// t = BC_a / (BC_a - BC_b), an entry if a is outside and an exit otherwise, and the kept part is
// [max entry, min exit].
// Why before the divide: the view volume is convex in homogeneous space (the intersection of six
// half-spaces through the origin), so the kept part is one interval in t, and a segment with an
// endpoint behind the eye (w <= 0), whose projection would wrap through infinity, is cut at the
// near plane without ever dividing by a vanishing w.
// Cost: 12 boundary coordinates and two outcodes; one division per plane actually crossed.
// When: 3D line primitives and wireframes. Triangles use the Sutherland-Hodgman clipper in
// homogeneous_clip.cpp, which needs polygons as output.
#include <zraster/line_clip.hpp>

#include <array>

namespace zraster {
namespace {

// Boundary coordinates in ClipPlaneBit order: near (depth min), far, left, right, bottom, top.
std::array<double, 6> boundary_coordinates(const glm::dvec4& p, ClipDepthRange range) {
    const double near = range == ClipDepthRange::ZeroToOne ? p.z : p.w + p.z;
    return {near, p.w - p.z, p.w + p.x, p.w - p.x, p.w + p.y, p.w - p.y};
}

std::uint32_t code_of(const std::array<double, 6>& bc) {
    std::uint32_t code = 0;
    // Written so that NaN is outside, as in clip.hpp's frustum_outcode.
    for (int k = 0; k < 6; ++k)
        if (!(bc[static_cast<std::size_t>(k)] >= 0.0)) code |= 1u << k;
    return code;
}

// Puts a point computed for plane k exactly on it: the rounding of a + t d leaves it within an
// ulp or so, and the divide would then give |x / w| slightly above 1.
glm::dvec4 snap_to_plane(glm::dvec4 p, int k, ClipDepthRange range) {
    switch (k) {
        case 0:
            p.z = range == ClipDepthRange::ZeroToOne ? 0.0 : -p.w;
            break;
        case 1:
            p.z = p.w;
            break;
        case 2:
            p.x = -p.w;
            break;
        case 3:
            p.x = p.w;
            break;
        case 4:
            p.y = -p.w;
            break;
        case 5:
            p.y = p.w;
            break;
        default:
            break;
    }
    return p;
}

}  // namespace

std::uint32_t outcode(const glm::dvec4& p, ClipDepthRange range) {
    return code_of(boundary_coordinates(p, range));
}

ClippedLine4 clip_line_homogeneous(const glm::dvec4& a, const glm::dvec4& b, ClipDepthRange range,
                                   LineClipStats* stats) {
    LineClipStats s;
    s.segments = 1;
    ClippedLine4 result;
    const std::array<double, 6> bc_a = boundary_coordinates(a, range);
    const std::array<double, 6> bc_b = boundary_coordinates(b, range);
    const std::uint32_t code_a = code_of(bc_a), code_b = code_of(bc_b);
    // A NaN endpoint is outside every plane, but need not share a bit with the other endpoint;
    // the parameters computed from it would be NaN too, so the segment is dropped here.
    const bool nan = glm::any(glm::isnan(a)) || glm::any(glm::isnan(b));
    if ((code_a | code_b) == 0) {
        ++s.trivial_accepts;
        result = {true, a, b, 0.0, 1.0};
    } else if ((code_a & code_b) != 0 || nan) {
        ++s.trivial_rejects;
    } else {
        double t0 = 0.0, t1 = 1.0;
        int enter = -1, leave = -1;
        // Only the planes the endpoints straddle constrain t in [0, 1]: both inside, no
        // constraint; both outside was a trivial reject.
        const std::uint32_t straddled = code_a ^ code_b;
        for (int k = 0; k < 6 && t0 <= t1; ++k) {
            if (!(straddled & (1u << k))) continue;
            const double ba = bc_a[static_cast<std::size_t>(k)];
            const double bb = bc_b[static_cast<std::size_t>(k)];
            const double t = ba / (ba - bb);  // ba - bb != 0: they have opposite signs
            ++s.subdivisions;
            if (ba < 0.0) {
                if (t > t0) t0 = t, enter = k;
            } else {
                if (t < t1) t1 = t, leave = k;
            }
        }
        if (t0 <= t1) {
            const glm::dvec4 d = b - a;
            result.visible = true;
            result.t0 = t0;
            result.t1 = t1;
            result.a = enter < 0 ? a : snap_to_plane(a + t0 * d, enter, range);
            result.b = leave < 0 ? b : snap_to_plane(a + t1 * d, leave, range);
        }
    }
    if (stats) *stats += s;
    return result;
}

}  // namespace zraster
