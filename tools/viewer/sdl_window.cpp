// `zraster view`'s window with SDL2: input in, zraster's frames out (the RGBA target copied to a
// streaming texture, drawn by SDL's software renderer; no GPU is involved in the picture).
#include <SDL.h>
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "command_line.hpp"
#include "debug_view_legend.hpp"
#include "rgba_image.hpp"
#include "view_hud.hpp"
#include "view_window.hpp"
#include "view_worker.hpp"

namespace zraster::cli {
namespace {

using Clock = std::chrono::steady_clock;

// SDL's video subsystem for the lifetime of the window.
class SdlVideo {
  public:
    SdlVideo() {
        SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
        // SDL would also try drivers that need no display (KMS/DRM, offscreen) and print
        // libwayland's complaints: without SDL_VIDEODRIVER, only a display that is there.
        if (std::getenv("SDL_VIDEODRIVER") == nullptr) {
            const char* driver = std::getenv("DISPLAY") != nullptr           ? "x11"
                                 : std::getenv("WAYLAND_DISPLAY") != nullptr ? "wayland"
                                                                             : nullptr;
            if (driver == nullptr)
                throw InputError("view",
                                 "cannot open a window (no display: DISPLAY and WAYLAND_DISPLAY "
                                 "are not set): set DISPLAY, or run it under xvfb-run");
            SDL_SetHint(SDL_HINT_VIDEODRIVER, driver);
        }
        if (SDL_Init(SDL_INIT_VIDEO) != 0)
            throw InputError("view", std::string("cannot open a window (") + SDL_GetError() +
                                         "): set DISPLAY, or run it under xvfb-run");
    }
    ~SdlVideo() { SDL_Quit(); }
    SdlVideo(const SdlVideo&) = delete;
    SdlVideo& operator=(const SdlVideo&) = delete;
};

struct WindowDeleter {
    void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
    void operator()(SDL_Renderer* r) const { SDL_DestroyRenderer(r); }
    void operator()(SDL_Texture* t) const { SDL_DestroyTexture(t); }
};
template <typename T>
using SdlPointer = std::unique_ptr<T, WindowDeleter>;

char key_of(SDL_Keycode code) {
    if (code == SDLK_ESCAPE) return kEscapeKey;
    if (code > 32 && code < 127) return char(code);  // SDL's keycodes of printable keys: ASCII
    return 0;
}

std::optional<InputEvent> translate(const SDL_Event& e) {
    InputEvent input;
    switch (e.type) {
        case SDL_QUIT:
            input.kind = InputEvent::Kind::Quit;
            return input;
        case SDL_KEYDOWN:
            input.kind = InputEvent::Kind::Key;
            input.key = key_of(e.key.keysym.sym);
            if (input.key == 0) return std::nullopt;
            return input;
        case SDL_MOUSEMOTION:
            input.kind = InputEvent::Kind::Drag;
            if (e.motion.state & SDL_BUTTON_LMASK)
                input.button = MouseButton::Left;
            else if (e.motion.state & SDL_BUTTON_RMASK)
                input.button = MouseButton::Right;
            else if (e.motion.state & SDL_BUTTON_MMASK)
                input.button = MouseButton::Middle;
            else
                return std::nullopt;
            input.dx = e.motion.xrel;
            input.dy = e.motion.yrel;
            return input;
        case SDL_MOUSEWHEEL:
            input.kind = InputEvent::Kind::Wheel;
            input.wheel = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
            return input;
        case SDL_WINDOWEVENT:
            if (e.window.event != SDL_WINDOWEVENT_SIZE_CHANGED) return std::nullopt;
            input.kind = InputEvent::Kind::Resize;
            input.width = e.window.data1;
            input.height = e.window.data2;
            return input;
        default:
            return std::nullopt;
    }
}

// Frames shown per second over the last second.
class FpsMeter {
  public:
    void shown(Clock::time_point t) {
        times_.push_back(t);
        while (times_.size() > 1 && t - times_.front() > std::chrono::seconds(1))
            times_.pop_front();
    }
    double fps() const {
        if (times_.size() < 2) return 0.0;
        const double span = std::chrono::duration<double>(times_.back() - times_.front()).count();
        return span > 0.0 ? double(times_.size() - 1) / span : 0.0;
    }

  private:
    std::deque<Clock::time_point> times_;
};

// A screenshot's name: zraster-view-N.png, the first N not taken in the working directory.
std::filesystem::path free_screenshot_name() {
    for (int n = 1;; ++n) {
        std::filesystem::path name = "zraster-view-" + std::to_string(n) + ".png";
        if (!std::filesystem::exists(name)) return name;
    }
}

class ViewerWindow {
  public:
    explicit ViewerWindow(ViewSetup& setup);
    ViewSummary run();

  private:
    void open_window();
    void apply_due_script_events();
    bool handle_input(int wait_ms);  // false: quit
    void request_frame_if_due();
    bool take_finished_frame();
    bool finished() const;
    void present(bool read_back);
    void write_screenshot(const std::filesystem::path& path);

    ViewSetup& s_;
    SdlVideo video_;
    SdlPointer<SDL_Window> window_;
    SdlPointer<SDL_Renderer> renderer_;
    SdlPointer<SDL_Texture> texture_;
    int texture_width_ = 0, texture_height_ = 0;
    FrameWorker worker_;
    std::optional<FrameResult> last_;  // the frame shown (the last one with an image)
    FrameResult latest_;               // the last frame drawn, for the HUD (errors too)
    std::optional<std::uint64_t> requested_;
    std::size_t next_script_event_ = 0;
    int screenshots_taken_ = 0;
    bool help_shown_ = false;
    FpsMeter fps_;
    RgbaImage shown_;  // what was last drawn into the window, HUD included
    ViewSummary summary_;
    std::string error_told_;  // the last refusal printed to stderr (each one once in a row)
};

ViewerWindow::ViewerWindow(ViewSetup& setup) : s_(setup), worker_(setup.scene, setup.world) {
    open_window();
}

void ViewerWindow::open_window() {
    const glm::ivec2 size = parse_size("--size", s_.state.render_arguments().size, kMaxViewport);
    window_.reset(SDL_CreateWindow(s_.title.c_str(), SDL_WINDOWPOS_UNDEFINED,
                                   SDL_WINDOWPOS_UNDEFINED, size.x, size.y, SDL_WINDOW_RESIZABLE));
    if (!window_)
        throw InputError("view", std::string("cannot open a window (") + SDL_GetError() + ")");
    renderer_.reset(SDL_CreateRenderer(window_.get(), -1, SDL_RENDERER_SOFTWARE));
    if (!renderer_)
        throw InputError("view",
                         std::string("cannot draw into the window (") + SDL_GetError() + ")");
}

void ViewerWindow::apply_due_script_events() {
    while (next_script_event_ < s_.script.size() &&
           s_.script[next_script_event_].frame <= summary_.frames_shown) {
        const InputEvent& e = s_.script[next_script_event_++].event;
        if (e.kind == InputEvent::Kind::Resize) SDL_SetWindowSize(window_.get(), e.width, e.height);
        s_.state.apply(e);
    }
}

bool ViewerWindow::handle_input(int wait_ms) {
    SDL_Event e;
    bool any = (wait_ms > 0 ? SDL_WaitEventTimeout(&e, wait_ms) : SDL_PollEvent(&e)) != 0;
    while (any) {
        if (const std::optional<InputEvent> input = translate(e)) s_.state.apply(*input);
        any = SDL_PollEvent(&e) != 0;
    }
    while (screenshots_taken_ < s_.state.screenshots_requested()) {
        ++screenshots_taken_;
        write_screenshot(free_screenshot_name());
    }
    if (help_shown_ != s_.state.help()) present(false);
    return !s_.state.quit();
}

void ViewerWindow::request_frame_if_due() {
    // Scripts and --frames draw frame after frame (for timing and replay); otherwise a frame is
    // drawn when the state changed.
    const bool continuous = s_.frames > 0 || !s_.script.empty();
    if (worker_.busy() || (requested_ == s_.state.serial() && !continuous)) return;
    requested_ = s_.state.serial();
    worker_.request({s_.state.render_arguments(), s_.state.debug_view(), s_.state.serial()});
}

bool ViewerWindow::take_finished_frame() {
    std::optional<FrameResult> frame = worker_.take();
    if (!frame) return false;
    summary_.render_ms.push_back(frame->render_ms);
    // A refused frame shows in the HUD, and on stderr too: with --no-hud or a script nobody
    // watches, it would pass without a word. (With --screenshot, the run ends refused if its
    // last frame is: told once, then.)
    if (!frame->error.empty() && frame->error != error_told_ && s_.screenshot.empty())
        std::fprintf(stderr, "warning: view: frame not drawn: %s\n", frame->error.c_str());
    error_told_ = frame->error;
    std::vector<std::uint8_t> rgba = std::move(frame->rgba);
    latest_ = *frame;
    if (!rgba.empty()) {
        last_ = std::move(*frame);
        last_->rgba = std::move(rgba);
    }
    ++summary_.frames_shown;
    fps_.shown(Clock::now());
    apply_due_script_events();
    // The next frame is drawn while this one goes to the window.
    if (!finished()) request_frame_if_due();
    present(false);
    return true;
}

bool ViewerWindow::finished() const {
    // --frames N: N frames shown, the last one showing every input so far.
    return s_.frames > 0 && summary_.frames_shown >= s_.frames && !worker_.busy() &&
           latest_.serial == s_.state.serial() && requested_ == s_.state.serial();
}

void ViewerWindow::present(bool read_back) {
    help_shown_ = s_.state.help();
    if (last_)
        shown_ = RgbaImage(last_->width, last_->height);
    else
        shown_ = RgbaImage(1, 1);
    if (last_) shown_.pixels = last_->rgba;
    if (s_.hud) {
        draw_debug_view_legend(shown_, latest_.view, latest_.stats.view_scale);
        draw_hud(shown_, hud_line(s_.state, latest_, fps_.fps()));
    }
    if (help_shown_) draw_help(shown_);
    if (!texture_ || texture_width_ != shown_.width || texture_height_ != shown_.height) {
        texture_.reset(SDL_CreateTexture(renderer_.get(), SDL_PIXELFORMAT_RGBA32,
                                         SDL_TEXTUREACCESS_STREAMING, shown_.width, shown_.height));
        if (!texture_)
            throw InputError("view", std::string("cannot make a texture (") + SDL_GetError() + ")");
        texture_width_ = shown_.width;
        texture_height_ = shown_.height;
    }
    SDL_UpdateTexture(texture_.get(), nullptr, shown_.pixels.data(), shown_.width * 4);
    SDL_RenderClear(renderer_.get());
    SDL_RenderCopy(renderer_.get(), texture_.get(), nullptr, nullptr);
    if (read_back) {
        int w = 0, h = 0;
        SDL_GetRendererOutputSize(renderer_.get(), &w, &h);
        RgbaImage window_pixels(std::max(w, 1), std::max(h, 1));
        if (SDL_RenderReadPixels(renderer_.get(), nullptr, SDL_PIXELFORMAT_RGBA32,
                                 window_pixels.pixels.data(), window_pixels.width * 4) == 0)
            shown_ = std::move(window_pixels);
    }
    SDL_RenderPresent(renderer_.get());
}

void ViewerWindow::write_screenshot(const std::filesystem::path& path) {
    present(true);  // shown_ now holds the window's pixels
    write_png8(path, shown_.width, shown_.height, 3, rgb_bytes(shown_));
}

ViewSummary ViewerWindow::run() {
    const Clock::time_point start = Clock::now();
    apply_due_script_events();
    for (;;) {
        const bool shown = take_finished_frame();
        if (finished()) break;
        request_frame_if_due();
        // Wait for input a little while a frame is drawn (the cores are the renderer's), longer
        // when there is nothing to draw.
        const int wait_ms = shown ? 0 : (worker_.busy() ? 1 : 10);
        if (!handle_input(wait_ms)) break;
    }
    summary_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    // A screenshot of a refused frame would be the last image drawn, or none: refused instead.
    if (!s_.screenshot.empty() && !latest_.error.empty())
        throw InputError("--screenshot", "the last frame was not drawn: " + latest_.error);
    if (!s_.screenshot.empty()) write_screenshot(s_.screenshot);
    return summary_;
}

}  // namespace

ViewSummary run_view_window(ViewSetup& setup) {
    ViewerWindow window(setup);
    return window.run();
}

}  // namespace zraster::cli
