// llvmpipe through EGL surfaceless + desktop GL 3.3 core, mirroring ../shared/tools/glbench.
#define GL_GLEXT_PROTOTYPES 1
#include "bench/gl_reference.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <dirent.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace zraster::bench {
namespace {

void check_gl(const char* where) {
    if (const GLenum e = glGetError())
        throw std::runtime_error(std::string("GL error ") + std::to_string(e) + " at " + where);
}

// glbench's shaders, verbatim (BENCH-SCENES.md "Render state and shading").
const char* const kVertexShader = R"(
layout(location = 0) in vec3 a_pos;
uniform mat4 u_mvp;
#ifdef PHONG
layout(location = 1) in vec3 a_nrm;
out vec3 v_pos;
out vec3 v_nrm;
#endif
void main() {
#ifdef PHONG
    v_pos = a_pos;  // model matrix is identity: object space == world space
    v_nrm = a_nrm;
#endif
    gl_Position = u_mvp * vec4(a_pos, 1.0);
}
)";

const char* const kFragmentShader = R"(
#if defined(PHONG)
in vec3 v_pos;
in vec3 v_nrm;
uniform vec3 u_eye;
uniform vec3 u_light;  // unit vector towards the light
out vec4 o_color;
void main() {
    vec3 N = normalize(v_nrm);
    if (!gl_FrontFacing) N = -N;
    vec3 V = normalize(u_eye - v_pos);
    vec3 H = normalize(u_light + V);
    float diff = max(dot(N, u_light), 0.0);
    float spec = pow(max(dot(N, H), 0.0), 32.0);
    o_color = vec4(vec3(0.8, 0.75, 0.7) * (0.15 + 0.85 * diff) + vec3(0.25 * spec), 1.0);
}
#elif defined(FLAT)
out vec4 o_color;
void main() { o_color = vec4(0.9, 0.6, 0.3, 1.0); }
#else
void main() {}
#endif
)";

// glbench's kLightDir: the float rounding of (-1/3, 2/3, 2/3).
const float kLightDir[3] = {-1.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f};

GLuint compile(GLenum type, const std::string& source) {
    const GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader compilation failed: ") + log);
    }
    return shader;
}

GLuint make_program(BenchMode mode) {
    std::string head = "#version 330 core\n";
    if (mode == BenchMode::Phong) head += "#define PHONG 1\n";
    if (mode == BenchMode::Flat) head += "#define FLAT 1\n";
    const GLuint program = glCreateProgram();
    const GLuint vs = compile(GL_VERTEX_SHADER, head + kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, head + kFragmentShader);
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("GL program link failed");
    return program;
}

}  // namespace

GlContext::GlContext(int threads) {
    // Software rendering on llvmpipe even where a GPU driver exists; the thread count is read
    // once, when the display is initialized.
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    if (threads > 0) setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

    const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!extensions || !std::strstr(extensions, "EGL_MESA_platform_surfaceless"))
        throw GlUnavailable(
            "EGL_MESA_platform_surfaceless is not available (is Mesa's EGL, "
            "libegl-mesa0, installed?)");
    EGLDisplay display =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
        throw GlUnavailable("eglInitialize failed on the surfaceless platform");
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw GlUnavailable("eglBindAPI(EGL_OPENGL_API) failed");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        throw GlUnavailable("eglCreateContext (OpenGL 3.3 core, no config) failed");
    }
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        eglTerminate(display);
        throw GlUnavailable("eglMakeCurrent without a surface failed");
    }
    const std::string name = renderer();
    if (name.find("llvmpipe") == std::string::npos) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        throw GlUnavailable("the GL renderer is '" + name + "', not llvmpipe");
    }
}

GlContext::~GlContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

std::string GlContext::renderer() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "";
}

std::string GlContext::version() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return s ? s : "";
}

int count_llvmpipe_threads() {
    int n = 0;
    if (DIR* dir = opendir("/proc/self/task")) {
        while (const dirent* entry = readdir(dir)) {
            std::ifstream comm(std::string("/proc/self/task/") + entry->d_name + "/comm");
            std::string name;
            if (std::getline(comm, name) && name.rfind("llvmpipe-", 0) == 0) ++n;
        }
        closedir(dir);
    }
    return n;
}

FlatMesh flatten_scene(const Scene& scene) {
    FlatMesh out;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes[instance.mesh];
        const auto base = static_cast<std::uint32_t>(out.vertex_count());
        const bool identity = instance.transform == glm::mat4(1.0f);
        const glm::mat3 normal_transform = normal_matrix(instance.transform);
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            glm::vec3 p = mesh.positions[v];
            glm::vec3 n = mesh.normals.empty() ? glm::vec3(0, 1, 0) : mesh.normals[v];
            if (!identity) {
                p = glm::vec3(instance.transform * glm::vec4(p, 1.0f));
                n = glm::normalize(normal_transform * n);
            }
            out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
            out.normals.insert(out.normals.end(), {n.x, n.y, n.z});
        }
        for (const std::uint32_t i : mesh.indices) out.indices.push_back(base + i);
    }
    return out;
}

std::uint64_t geometry_hash(const FlatMesh& mesh) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const std::uint32_t i : mesh.indices) {
        unsigned char bytes[12];
        std::memcpy(bytes, &mesh.positions[3 * std::size_t(i)], 12);  // little-endian host
        for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
    }
    return h;
}

GlMesh::GlMesh(const FlatMesh& mesh) : index_count_(mesh.indices.size()) {
    glGenBuffers(3, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.positions.size() * sizeof(float)),
                 mesh.positions.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.normals.size() * sizeof(float)),
                 mesh.normals.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    // The element buffer is bound to each renderer's vertex array, not here.
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffers_[2]);
    glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    check_gl("mesh upload");
}

GlMesh::~GlMesh() {
    glDeleteBuffers(3, buffers_);
}

GlRenderer::GlRenderer(const GlMesh& mesh, BenchMode mode, int width, int height, bool cull,
                       const Camera& camera)
    : mesh_(mesh), mode_(mode), width_(width), height_(height), cull_(cull) {
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(2, renderbuffers_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              renderbuffers_[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              renderbuffers_[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("GL framebuffer incomplete");
    // Depth mode draws no color (draw buffer NONE is framebuffer state).
    glDrawBuffer(mode == BenchMode::Depth ? GL_NONE : GL_COLOR_ATTACHMENT0);

    // Positions at location 0; normals at 1 only for phong (depth and flat fetch positions only).
    glGenVertexArrays(1, &vertex_array_);
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, mesh.position_buffer());
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    if (mode == BenchMode::Phong) {
        glBindBuffer(GL_ARRAY_BUFFER, mesh.normal_buffer());
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(1);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.index_buffer());
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    // The same float MVP and eye as zraster (Camera::view_projection rounds as glbench does).
    program_ = make_program(mode);
    glUseProgram(program_);
    const double aspect = double(width) / double(height);
    const glm::mat4 mvp = camera.view_projection(aspect);
    glUniformMatrix4fv(glGetUniformLocation(program_, "u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
    if (mode == BenchMode::Phong) {
        const glm::vec3 eye(camera.eye);
        glUniform3fv(glGetUniformLocation(program_, "u_eye"), 1, glm::value_ptr(eye));
        glUniform3fv(glGetUniformLocation(program_, "u_light"), 1, kLightDir);
    }
    check_gl("renderer setup");
}

GlRenderer::~GlRenderer() {
    glDeleteProgram(program_);
    glDeleteVertexArrays(1, &vertex_array_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(2, renderbuffers_);
}

// Several renderers share the context: each frame sets the whole (cheap) state it needs.
void GlRenderer::bind_state() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glBindVertexArray(vertex_array_);
    glUseProgram(program_);
    glViewport(0, 0, width_, height_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    if (cull_)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const GLboolean color = mode_ == BenchMode::Depth ? GL_FALSE : GL_TRUE;
    glColorMask(color, color, color, color);
}

void GlRenderer::draw() {
    bind_state();
    glClear(mode_ == BenchMode::Depth ? GL_DEPTH_BUFFER_BIT
                                      : GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(mesh_.index_count()), GL_UNSIGNED_INT, nullptr);
    glFinish();
}

std::vector<float> GlRenderer::read_depth() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    std::vector<float> bottom_first(std::size_t(width_) * std::size_t(height_));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, bottom_first.data());
    check_gl("depth readback");
    std::vector<float> top_first(bottom_first.size());
    for (int y = 0; y < height_; ++y)
        std::copy_n(&bottom_first[std::size_t(height_ - 1 - y) * std::size_t(width_)], width_,
                    &top_first[std::size_t(y) * std::size_t(width_)]);
    return top_first;
}

std::vector<std::uint8_t> GlRenderer::read_color() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    const std::size_t row = std::size_t(width_) * 4;
    std::vector<std::uint8_t> bottom_first(row * std::size_t(height_));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_first.data());
    check_gl("color readback");
    std::vector<std::uint8_t> top_first(bottom_first.size());
    for (int y = 0; y < height_; ++y)
        std::copy_n(&bottom_first[std::size_t(height_ - 1 - y) * row], row,
                    &top_first[std::size_t(y) * row]);
    return top_first;
}

DepthComparison compare_depth(const std::vector<float>& gl, const std::vector<float>& zraster) {
    if (gl.size() != zraster.size()) throw std::runtime_error("depth buffers differ in size");
    DepthComparison c;
    c.pixels = gl.size();
    for (std::size_t i = 0; i < gl.size(); ++i) {
        const bool g = gl[i] < 1.0f, z = zraster[i] < 1.0f;
        if (g && z) {
            ++c.both_covered;
            const double d = std::fabs(double(gl[i]) - double(zraster[i]));
            c.max_abs_difference = std::max(c.max_abs_difference, d);
            if (d >= 1e-5) ++c.differing_over_1e5;
        } else if (g) {
            ++c.only_gl;
        } else if (z) {
            ++c.only_zraster;
        } else {
            ++c.both_empty;
        }
    }
    return c;
}

ColorComparison compare_color(const std::vector<std::uint8_t>& gl,
                              const std::vector<std::uint8_t>& zraster,
                              const std::vector<float>& gl_depth,
                              const std::vector<float>& zraster_depth) {
    if (gl.size() != zraster.size() || gl.size() != gl_depth.size() * 4 ||
        zraster_depth.size() != gl_depth.size())
        throw std::runtime_error("color buffers differ in size");
    ColorComparison c;
    for (std::size_t i = 0; i < gl_depth.size(); ++i) {
        if (!(gl_depth[i] < 1.0f && zraster_depth[i] < 1.0f)) continue;
        ++c.compared;
        int worst = 0;
        for (std::size_t k = 0; k < 3; ++k)
            worst = std::max(worst, std::abs(int(gl[i * 4 + k]) - int(zraster[i * 4 + k])));
        c.max_difference = std::max(c.max_difference, worst);
        if (worst > 1) ++c.over_1;
        if (worst > 8) ++c.over_8;
    }
    return c;
}

}  // namespace zraster::bench
