// Mesa llvmpipe as an in-process reference: an EGL surfaceless desktop GL 3.3 core context and a
// renderer that draws a zraster scene exactly as ../shared/tools/glbench does (same FBO formats,
// shaders, state and frame = clear + draw + glFinish). Used by llvmpipe_compare and by the
// cross-check test, so both compare against the same GL code.
#pragma once
#include <zraster/bench_workload.hpp>
#include <zraster/camera.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace zraster::bench {

// Thrown when no llvmpipe context can be made (no EGL_MESA_platform_surfaceless, no Mesa driver).
class GlUnavailable : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// One context per process: llvmpipe reads GALLIUM_DRIVER, LIBGL_ALWAYS_SOFTWARE and
// LP_NUM_THREADS when the display is initialized, so they are set here first.
// threads > 0 sets LP_NUM_THREADS; 0 keeps llvmpipe's default (one thread per CPU).
class GlContext {
  public:
    explicit GlContext(int threads);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version() const;

  private:
    void* display_ = nullptr;
    void* context_ = nullptr;
};

// llvmpipe's rasterizer threads in this process (named "llvmpipe-N"; they exist once a context
// has rendered).
int count_llvmpipe_threads();

// A scene as one draw call: world-space float positions and normals, 32-bit indices, instances
// concatenated in order (identity transforms, as the benchmark scenes have, copy the floats
// unchanged).
struct FlatMesh {
    std::vector<float> positions;  // xyz per vertex
    std::vector<float> normals;    // xyz per vertex
    std::vector<std::uint32_t> indices;
    std::size_t vertex_count() const { return positions.size() / 3; }
    std::size_t triangle_count() const { return indices.size() / 3; }
};
FlatMesh flatten_scene(const Scene& scene);
// geometry_hash of BENCH-SCENES.md over the flattened mesh.
std::uint64_t geometry_hash(const FlatMesh& mesh);

// Vertex, normal and index buffers of one mesh; shared by the renderers of its modes.
class GlMesh {
  public:
    explicit GlMesh(const FlatMesh& mesh);
    ~GlMesh();
    GlMesh(const GlMesh&) = delete;
    GlMesh& operator=(const GlMesh&) = delete;

    unsigned position_buffer() const { return buffers_[0]; }
    unsigned normal_buffer() const { return buffers_[1]; }
    unsigned index_buffer() const { return buffers_[2]; }
    std::size_t index_count() const { return index_count_; }

  private:
    unsigned buffers_[3] = {0, 0, 0};
    std::size_t index_count_ = 0;
};

// One (mesh, mode, size, camera) as glbench draws it, into its own FBO: RGBA8 color +
// DEPTH_COMPONENT32F depth renderbuffers.
class GlRenderer {
  public:
    GlRenderer(const GlMesh& mesh, BenchMode mode, int width, int height, bool cull,
               const Camera& camera);
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // One frame: glClear + glDrawElements + glFinish (glbench's timed unit).
    void draw();
    // Window depth in [0, 1], top row first (as RenderTargets::depth).
    std::vector<float> read_depth() const;
    // RGBA8, top row first (as RenderTargets::color).
    std::vector<std::uint8_t> read_color() const;

  private:
    void bind_state() const;

    const GlMesh& mesh_;
    BenchMode mode_;
    int width_, height_;
    bool cull_;
    unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0}, vertex_array_ = 0, program_ = 0;
};

// Depth buffers compared pixel by pixel; a pixel is covered when its depth is below the clear
// value 1.0 (LESS against 1.0 never stores 1.0).
struct DepthComparison {
    std::size_t pixels = 0;
    std::size_t both_empty = 0, both_covered = 0, only_gl = 0, only_zraster = 0;
    double max_abs_difference = 0.0;     // over pixels both cover
    std::size_t differing_over_1e5 = 0;  // covered by both, |difference| >= 1e-5
    double coverage_agreement() const {
        return pixels ? double(both_empty + both_covered) / double(pixels) : 1.0;
    }
};
DepthComparison compare_depth(const std::vector<float>& gl, const std::vector<float>& zraster);

// RGBA8 images compared over the pixels both depth buffers cover.
struct ColorComparison {
    std::size_t compared = 0;
    std::size_t over_1 = 0, over_8 = 0;  // pixels whose largest channel difference exceeds it
    int max_difference = 0;
};
ColorComparison compare_color(const std::vector<std::uint8_t>& gl,
                              const std::vector<std::uint8_t>& zraster,
                              const std::vector<float>& gl_depth,
                              const std::vector<float>& zraster_depth);

}  // namespace zraster::bench
