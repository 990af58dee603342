// OcclusionBuffer (include/zraster/occlusion_buffer.hpp): storage, occluder batches, and the
// conversion of boxes, triangles and NDC rectangles into conservative pixel rectangles.
#include <zraster/error.hpp>
#include <zraster/occlusion_buffer.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "occlusion/occluder_setup.hpp"
#include "occlusion/occlusion_kernel.hpp"

namespace zraster {

namespace {

static_assert(OcclusionBuffer::kTileWidth == detail::kOcclusionTileWidth &&
              OcclusionBuffer::kTileHeight == detail::kOcclusionTileHeight);
static_assert(sizeof(glm::vec4) == 4 * sizeof(float));  // clip positions are read as floats

constexpr int kMaxSide = 16384;

// Written out: glm's operators are not always inlined at -O2, and box tests are short.
inline glm::vec4 transform(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec4((m[0].x * p.x + m[1].x * p.y) + (m[2].x * p.z + m[3].x),
                     (m[0].y * p.x + m[1].y * p.y) + (m[2].y * p.z + m[3].y),
                     (m[0].z * p.x + m[1].z * p.y) + (m[2].z * p.z + m[3].z),
                     (m[0].w * p.x + m[1].w * p.y) + (m[2].w * p.z + m[3].w));
}
inline glm::vec4 scaled(const glm::vec4& v, float s) {
    return glm::vec4(v.x * s, v.y * s, v.z * s, v.w * s);
}
inline glm::vec4 sum(const glm::vec4& a, const glm::vec4& b) {
    return glm::vec4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
}

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

struct OcclusionBuffer::Impl {
    int width = 0, height = 0;
    detail::TileGrid grid;
    detail::StripStorage rows;     // see TileGrid
    std::vector<float> coarse;     // see TileGrid
    std::vector<float> block_max;  // see TileGrid
    std::unique_ptr<detail::OccluderBatch> batch = std::make_unique<detail::OccluderBatch>();
    std::size_t batch_size = 0;
    std::vector<glm::vec4> transformed;  // scratch for render_occluders with a matrix
    bool simd = true;
    std::uint64_t rasterized = 0;

    // Tiles touched since the last refresh of the coarse levels (inclusive; empty when x0 > x1).
    int dirty_x0 = 1 << 30, dirty_y0 = 1 << 30, dirty_x1 = -1, dirty_y1 = -1;

    void refresh_coarse_levels() {
        if (dirty_x0 <= dirty_x1) {
            if (simd)
                detail::refresh_coarse_levels(grid, dirty_x0, dirty_y0, dirty_x1, dirty_y1);
            else
                detail::refresh_coarse_levels_scalar(grid, dirty_x0, dirty_y0, dirty_x1, dirty_y1);
        }
        dirty_x0 = dirty_y0 = 1 << 30;
        dirty_x1 = dirty_y1 = -1;
    }

    void flush() {
        if (batch_size == 0) return;
        // Pixel bounds first (a loop the compiler vectorizes), tiles once.
        int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
        const detail::OccluderBatch& b = *batch;
        for (std::size_t i = 0; i < batch_size; ++i) {
            x0 = std::min(x0, b.x0[i]);
            x1 = std::max(x1, b.x1[i]);
            y0 = std::min(y0, b.y0[i]);
            y1 = std::max(y1, b.y1[i]);
        }
        dirty_x0 = std::min(dirty_x0, x0 / kTileWidth);
        dirty_y0 = std::min(dirty_y0, y0 / kTileHeight);
        dirty_x1 = std::max(dirty_x1, x1 / kTileWidth);
        dirty_y1 = std::max(dirty_y1, y1 / kTileHeight);
        if (simd)
            detail::rasterize_occluders(b, batch_size, grid);
        else
            detail::rasterize_occluders_scalar(b, batch_size, grid);
        rasterized += batch_size;
        batch_size = 0;
    }

    bool occluded(int x0, int y0, int x1, int y1, float depth) const {
        return simd ? detail::rect_occluded(grid, x0, y0, x1, y1, depth)
                    : detail::rect_occluded_scalar(grid, x0, y0, x1, y1, depth);
    }

    // The conservative answer for an object whose clip-space points are `points`.
    OcclusionResult test_points(const glm::vec4* points, int n) const;
    // The same for window-space bounds (x right, y down, in pixels) and nearest depth, all
    // finite, the object in front of the near plane and not entirely outside the view.
    OcclusionResult test_window_rect(float xmin, float xmax, float ymin, float ymax,
                                     float nearest) const;
};

OcclusionBuffer::OcclusionBuffer() : impl_(std::make_unique<Impl>()) {}

OcclusionBuffer::OcclusionBuffer(int width, int height) : OcclusionBuffer() {
    set_resolution(width, height);
}

OcclusionBuffer::~OcclusionBuffer() = default;
OcclusionBuffer::OcclusionBuffer(OcclusionBuffer&&) noexcept = default;
OcclusionBuffer& OcclusionBuffer::operator=(OcclusionBuffer&&) noexcept = default;

void OcclusionBuffer::set_resolution(int width, int height) {
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        throw InputError("", "occlusion buffer size " + std::to_string(width) + "x" +
                                 std::to_string(height) + " out of range (1.." +
                                 std::to_string(kMaxSide) + " per side)");
    Impl& m = *impl_;
    m.width = width;
    m.height = height;
    m.grid.tiles_x = (width + kTileWidth - 1) / kTileWidth;
    m.grid.tiles_y = (height + kTileHeight - 1) / kTileHeight;
    m.rows.attach(m.grid);
    // Padded: the rectangle test loads whole vectors of them.
    m.coarse.resize(2 * static_cast<std::size_t>(m.grid.tiles_x) * m.grid.tiles_y +
                    detail::kCoarsePadding);
    m.block_max.resize(detail::block_max_size(m.grid.tiles_x, m.grid.tiles_y));
    m.grid.width = width;
    m.grid.height = height;
    m.grid.coarse = m.coarse.data();
    m.grid.block_max = m.block_max.data();
    clear();
}

int OcclusionBuffer::width() const {
    return impl_->width;
}
int OcclusionBuffer::height() const {
    return impl_->height;
}
void OcclusionBuffer::set_simd(bool on) {
    impl_->simd = on;
}
const char* OcclusionBuffer::simd_target() {
    return detail::occlusion_kernel_target();
}

void OcclusionBuffer::clear() {
    impl_->rows.clear();
    std::fill(impl_->coarse.begin(), impl_->coarse.end(), detail::kClearFarDepth);
    std::fill(impl_->block_max.begin(), impl_->block_max.end(), detail::kClearFarDepth);
    impl_->rasterized = 0;
}

void OcclusionBuffer::render_occluders(std::span<const glm::vec4> clip_positions,
                                       std::span<const std::uint32_t> indices,
                                       const OccluderOptions& options) {
    Impl& m = *impl_;
    if (m.width == 0) return;
    detail::OccluderSource source;
    source.clip = reinterpret_cast<const float*>(clip_positions.data());
    source.vertex_count = clip_positions.size();
    source.indices = indices.data();
    source.triangle_count = indices.size() / 3;
    source.width = m.width;
    source.height = m.height;
    source.cull_back = options.cull == OccluderCull::Back;
    source.cull_front = options.cull == OccluderCull::Front;
    source.front_face_clockwise = options.front_face_clockwise;
    // NaN or negative: none; huge: nothing is covered (still conservative).
    source.subpixel_margin =
        options.subpixel_margin > 0.0f ? std::min(options.subpixel_margin, 1e6f) : 0.0f;
    const std::size_t triangles = indices.size() / 3;
    // Set up a group, rasterize it while it is in L1, next group.
    for (std::size_t first = 0; first < triangles; first += detail::kSetupGroup) {
        const std::size_t count = std::min(detail::kSetupGroup, triangles - first);
        m.batch_size = m.simd ? detail::setup_occluders(source, first, count, *m.batch)
                              : detail::setup_occluders_scalar(source, first, count, *m.batch);
        m.flush();
    }
    m.refresh_coarse_levels();
}

void OcclusionBuffer::render_occluders(std::span<const glm::vec3> positions,
                                       std::span<const std::uint32_t> indices,
                                       const glm::mat4& to_clip, const OccluderOptions& options) {
    std::vector<glm::vec4>& clip = impl_->transformed;
    clip.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
        clip[i] = to_clip * glm::vec4(positions[i], 1.0f);
    render_occluders(std::span<const glm::vec4>(clip), indices, options);
}

OcclusionResult OcclusionBuffer::Impl::test_points(const glm::vec4* points, int n) const {
    unsigned outside_all = 0x3f;
    bool crosses_near = false;
    for (int i = 0; i < n; ++i) {
        const glm::vec4& p = points[i];
        if (!finite(p)) return OcclusionResult::Visible;
        unsigned code = 0;
        if (p.x < -p.w) code |= 1;
        if (p.x > p.w) code |= 2;
        if (p.y < -p.w) code |= 4;
        if (p.y > p.w) code |= 8;
        if (p.z > p.w) code |= 16;
        if (p.z < -p.w) code |= 32;
        outside_all &= code;
        crosses_near |= (code & 32) != 0 || !(p.w > 0.0f);
    }
    if (outside_all) return OcclusionResult::OutsideView;
    if (crosses_near || width == 0) return OcclusionResult::Visible;
    float xmin = HUGE_VALF, xmax = -HUGE_VALF, ymin = HUGE_VALF, ymax = -HUGE_VALF;
    float nearest = HUGE_VALF;
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    for (int i = 0; i < n; ++i) {
        const glm::vec4& p = points[i];
        const float inv_w = 1.0f / p.w;
        const float x = (p.x * inv_w * 0.5f + 0.5f) * w;
        const float y = (0.5f - p.y * inv_w * 0.5f) * h;
        xmin = x < xmin ? x : xmin;
        xmax = x > xmax ? x : xmax;
        ymin = y < ymin ? y : ymin;
        ymax = y > ymax ? y : ymax;
        const float z = p.z * inv_w * 0.5f + 0.5f;
        nearest = z < nearest ? z : nearest;
    }
    return test_window_rect(xmin, xmax, ymin, ymax, nearest);
}

OcclusionResult OcclusionBuffer::Impl::test_window_rect(float xmin, float xmax, float ymin,
                                                        float ymax, float nearest) const {
    using detail::WindowRectResult;
    const WindowRectResult r =
        simd ? detail::window_rect_test(grid, xmin, xmax, ymin, ymax, nearest)
             : detail::window_rect_test_scalar(grid, xmin, xmax, ymin, ymax, nearest);
    return r == WindowRectResult::kOccluded      ? OcclusionResult::Occluded
           : r == WindowRectResult::kOutsideView ? OcclusionResult::OutsideView
                                                 : OcclusionResult::Visible;
}

OcclusionResult OcclusionBuffer::test_rect(glm::vec2 ndc_min, glm::vec2 ndc_max,
                                           float nearest_depth) const {
    if (!std::isfinite(ndc_min.x) || !std::isfinite(ndc_min.y) || !std::isfinite(ndc_max.x) ||
        !std::isfinite(ndc_max.y) || std::isnan(nearest_depth))
        return OcclusionResult::Visible;
    if (ndc_max.x < -1.0f || ndc_min.x > 1.0f || ndc_max.y < -1.0f || ndc_min.y > 1.0f ||
        nearest_depth > 1.0f)
        return OcclusionResult::OutsideView;
    if (nearest_depth < 0.0f || ndc_min.x > ndc_max.x || ndc_min.y > ndc_max.y)
        return OcclusionResult::Visible;
    const Impl& m = *impl_;
    if (m.width == 0) return OcclusionResult::Visible;
    const float w = static_cast<float>(m.width), h = static_cast<float>(m.height);
    return m.test_window_rect((ndc_min.x * 0.5f + 0.5f) * w, (ndc_max.x * 0.5f + 0.5f) * w,
                              (0.5f - ndc_max.y * 0.5f) * h, (0.5f - ndc_min.y * 0.5f) * h,
                              nearest_depth);
}

OcclusionResult OcclusionBuffer::test_pixel_rect(int x0, int y0, int x1, int y1,
                                                 float nearest_depth) const {
    const Impl& m = *impl_;
    if (std::isnan(nearest_depth)) return OcclusionResult::Visible;
    if (x1 < 0 || y1 < 0 || x0 >= m.width || y0 >= m.height || x0 > x1 || y0 > y1 ||
        nearest_depth > 1.0f)
        return OcclusionResult::OutsideView;
    if (nearest_depth < 0.0f) return OcclusionResult::Visible;
    return m.occluded(std::max(x0, 0), std::max(y0, 0), std::min(x1, m.width - 1),
                      std::min(y1, m.height - 1), nearest_depth)
               ? OcclusionResult::Occluded
               : OcclusionResult::Visible;
}

OcclusionResult OcclusionBuffer::test_box(const Bounds3f& box, const glm::mat4& to_clip) const {
    if (box.empty()) return OcclusionResult::OutsideView;
    // Corners as one transformed corner plus the transformed edge vectors: 3 matrix columns
    // scaled and 7 additions instead of 8 full transforms (the rounding differs by a few ulps,
    // far inside the margins of test_window_rect).
    const glm::vec4 origin = transform(to_clip, box.lo);
    const glm::vec3 size = box.hi - box.lo;
    const glm::vec4 dx = scaled(to_clip[0], size.x), dy = scaled(to_clip[1], size.y);
    const glm::vec4 dz = scaled(to_clip[2], size.z);
    const glm::vec4 odx = sum(origin, dx), ody = sum(origin, dy), odz = sum(origin, dz);
    const glm::vec4 corners[8] = {origin, odx,          ody,          sum(odx, dy),
                                  odz,    sum(odx, dz), sum(ody, dz), sum(sum(odx, dy), dz)};
    return impl_->test_points(corners, 8);
}

OcclusionResult OcclusionBuffer::test_triangle(const glm::vec4& a, const glm::vec4& b,
                                               const glm::vec4& c) const {
    const glm::vec4 points[3] = {a, b, c};
    return impl_->test_points(points, 3);
}

void OcclusionBuffer::depth_bounds(std::span<float> out) const {
    const Impl& m = *impl_;
    const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
    for (std::size_t i = 0; i < std::min(n, out.size()); ++i) {
        const int x = static_cast<int>(i % m.width), y = static_cast<int>(i / m.width);
        const std::size_t at = detail::row_index(m.grid, x / kTileWidth, y);
        const bool masked = (m.grid.mask[at] >> (x % kTileWidth)) & 1u;
        out[i] = masked ? m.grid.near_depth[at] : m.grid.far_depth[at];
    }
}

std::vector<std::byte> OcclusionBuffer::raw_storage() const {
    const detail::StripStorage& rows = impl_->rows;
    const auto mask = std::as_bytes(std::span<const std::uint32_t>(rows.mask.get(), rows.rows));
    const auto depth = std::as_bytes(std::span<const float>(rows.depth.get(), 2 * rows.rows));
    std::vector<std::byte> out(mask.begin(), mask.end());
    out.insert(out.end(), depth.begin(), depth.end());
    return out;
}

std::uint64_t OcclusionBuffer::occluder_triangles_rasterized() const {
    return impl_->rasterized;
}

}  // namespace zraster
