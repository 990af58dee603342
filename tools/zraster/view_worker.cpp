// The viewer's render thread.
#include "view_worker.hpp"

#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>

#include <fmt/format.h>

#include <chrono>
#include <new>

#include "command_line.hpp"

namespace zraster::cli {

FrameResult FrameDrawer::draw(const FrameRequest& request) {
    FrameResult result;
    result.serial = request.serial;
    const auto start = std::chrono::steady_clock::now();
    try {
        const RenderArguments& a = request.arguments;
        RenderOptions options = make_render_options(a, world_, std::nullopt);
        options.view = request.view;
        result.width = options.width;
        result.height = options.height;
        if (renders_with_pipeline(a)) {
            const RenderResult& frame = renderer_.render(scene_, options);
            result.rgba = frame.targets.color;
            result.stats = frame.stats;
            result.view = options.view;
        } else {
            VisibilityStats visibility;
            ABufferStats abuffer;
            RenderResult frame = render_frame(a, scene_, options, &visibility, &abuffer);
            result.rgba = std::move(frame.targets.color);
            result.stats = frame.stats;
            result.polygons = visibility.polygons;
        }
    } catch (const LimitExceeded& e) {
        result.error = std::string(e.what()) + limit_advice(e.limit());
    } catch (const InputError& e) {
        result.error = e.what();
    } catch (const std::bad_alloc&) {
        result.error = "out of memory";
    }
    if (!result.error.empty()) result.rgba.clear();
    result.render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

FrameWorker::FrameWorker(const Scene& scene, std::span<const glm::vec3> world)
    : drawer_(scene, world), thread_([this] { run(); }) {}

FrameWorker::~FrameWorker() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void FrameWorker::request(FrameRequest request) {
    {
        const std::lock_guard lock(mutex_);
        pending_ = std::move(request);
    }
    wake_.notify_all();
}

std::optional<FrameResult> FrameWorker::take() {
    const std::lock_guard lock(mutex_);
    std::optional<FrameResult> result = std::move(finished_);
    finished_.reset();
    return result;
}

bool FrameWorker::busy() const {
    const std::lock_guard lock(mutex_);
    // A finished frame not yet taken counts: a new request then would outrun it.
    return drawing_ || pending_.has_value() || finished_.has_value();
}

void FrameWorker::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
        if (stopping_) return;
        const FrameRequest request = std::move(*pending_);
        pending_.reset();
        drawing_ = true;
        lock.unlock();
        FrameResult result = drawer_.draw(request);
        lock.lock();
        finished_ = std::move(result);
        drawing_ = false;
    }
}

}  // namespace zraster::cli
