// See batch_job.hpp.
#include "batch_job.hpp"

#include <zraster/error.hpp>
#include <zraster/output_files.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "command_line.hpp"
#include "flag_effects.hpp"
#include "render_outputs.hpp"

namespace zraster::cli {
namespace {

// A FILE* the frame prints its notes to, its warnings read back as lines (without "warning: ":
// a record's warnings are warnings).
class FrameNotes {
  public:
    FrameNotes() : file_(open_memstream(&buffer_, &size_)) {}
    ~FrameNotes() {
        if (file_ != nullptr) std::fclose(file_);
        std::free(buffer_);
    }
    FrameNotes(const FrameNotes&) = delete;
    FrameNotes& operator=(const FrameNotes&) = delete;
    std::FILE* file() const { return file_; }
    std::vector<std::string> lines() {
        std::vector<std::string> out;
        if (file_ == nullptr || std::fflush(file_) != 0) return out;
        std::string_view text(buffer_, size_);
        while (!text.empty()) {
            const std::size_t end = std::min(text.find('\n'), text.size());
            std::string_view line = text.substr(0, end);
            text.remove_prefix(std::min(end + 1, text.size()));
            // (Other notes, such as a debug view's legend, are not warnings.)
            if (line.starts_with("warning: ")) out.emplace_back(line.substr(9));
        }
        return out;
    }

  private:
    char* buffer_ = nullptr;
    std::size_t size_ = 0;
    std::FILE* file_;
};

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string output_path(const BatchSettings& s, const BatchInput& input, const BatchView& view,
                        const std::string& tail) {
    return (s.out_dir / (input.stem + view.suffix + tail)).string();
}

bool stopping(const std::atomic<bool>* stop) {
    return stop != nullptr && stop->load(std::memory_order_relaxed);
}

// The message of a failure, naming the input first (the loader's do; a flag's or an output's
// name the option or the output path).
std::string error_line(const std::string& input, const std::string& what) {
    std::string line = what.starts_with(input + ": ") ? what : input + ": " + what;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    return line;
}

// The loader refuses a file over LoadOptions::max_triangles before reading its geometry; that
// limit is the batch's --max-triangles, or what --max-memory leaves room for.
Scene load_within_limits(const BatchInput& input, const LoadOptions& options,
                         std::vector<std::string>& warnings,
                         std::vector<std::filesystem::path>& files_read) {
    try {
        return load_scene(input.source, options, &warnings, &files_read);
    } catch (const LimitExceeded& e) {
        if (e.limit() != "max_triangles") throw;
        // The advice in full: a plain InputError, so that no other advice is appended.
        throw InputError(e.file(), fmt::format("{}; raise it with --max-triangles N (or "
                                               "--max-memory, at {} bytes a triangle)",
                                               e.cause(), kMinBytesPerTriangle));
    }
}

}  // namespace

RenderArguments view_arguments(const BatchInput& input, const BatchSettings& s,
                               const BatchView& view) {
    RenderArguments a = with_view(s.render, view);
    a.scene = input.source.string();
    const BatchOutputKinds& k = s.outputs;
    a.output = output_path(s, input, view, ".png");
    a.depth_out = k.depth.empty() ? "" : output_path(s, input, view, "_depth." + k.depth);
    a.depth_camera.z_out = k.z.empty() ? "" : output_path(s, input, view, "_z." + k.z);
    a.depth_camera.range_out = k.range ? output_path(s, input, view, "_range.npy") : "";
    a.normal_out = k.normal ? output_path(s, input, view, "_normal.png") : "";
    a.id_out = k.id.empty() ? "" : output_path(s, input, view, "_id." + k.id);
    a.depth_camera.points_out = k.points ? output_path(s, input, view, "_points.ply") : "";
    a.depth_camera.camera_json = k.camera_json ? output_path(s, input, view, "_camera.json") : "";
    return a;
}

std::vector<std::filesystem::path> planned_outputs(const BatchInput& input,
                                                   const BatchSettings& settings) {
    std::vector<std::filesystem::path> paths;
    for (const BatchView& view : settings.views) {
        const RenderArguments a = view_arguments(input, settings, view);
        for (const std::string* p :
             {&a.output, &a.depth_out, &a.depth_camera.z_out, &a.depth_camera.range_out,
              &a.normal_out, &a.id_out, &a.depth_camera.points_out, &a.depth_camera.camera_json})
            if (!p->empty()) paths.emplace_back(*p);
    }
    return paths;
}

void check_batch_settings(const BatchSettings& settings) {
    for (const std::string& w : check_flags_take_effect(settings.render))
        fmt::print(stderr, "warning: {}\n", w);
    // A stand-in input: its outputs' paths go through every check a real one's will.
    const BatchInput probe{"probe", ".zraster-batch-check"};
    for (const BatchView& view : settings.views) {
        const RenderArguments a = view_arguments(probe, settings, view);
        OutputFiles outputs;
        check_render_outputs(a, outputs);
        check_frame_arguments(a);
        const RenderOptions options = make_render_options(a, std::span<const glm::vec3>(), {});
        apply_intrinsics(a.depth_camera, *options.camera, options.width, options.height);
    }
}

BatchRecord run_batch_job(const BatchInput& input, const BatchSettings& settings,
                          const std::atomic<bool>* stop, Renderer* renderer) {
    BatchRecord record;
    record.input = input.source.string();
    const std::vector<std::filesystem::path> planned = planned_outputs(input, settings);
    const std::vector<std::string>* reads =
        settings.force ? nullptr : settings.history->written(record.input, planned);
    if (reads && outputs_up_to_date(input.source, planned, *reads)) {
        record.status = BatchStatus::Skipped;
        for (const std::filesystem::path& p : planned) record.outputs.push_back(p.string());
        record.reads = *reads;
        return record;
    }
    const auto dropped = [&] {
        record.status = BatchStatus::Dropped;
        return record;
    };
    try {
        if (stopping(stop)) return dropped();
        std::vector<RenderArguments> views;
        OutputFiles outputs;
        for (const BatchView& view : settings.views) {
            views.push_back(view_arguments(input, settings, view));
            std::filesystem::create_directories(
                std::filesystem::path(views.back().output).parent_path());
            check_render_outputs(views.back(), outputs);
        }
        outputs.check_input(input.source, "");

        const Clock::time_point load_start = Clock::now();
        Scene scene;
        std::vector<std::filesystem::path> files_read;
        try {
            scene = load_within_limits(input, settings.load, record.warnings, files_read);
        } catch (...) {
            record.load_ms = ms_since(load_start);
            throw;
        }
        record.load_ms = ms_since(load_start);
        for (const std::filesystem::path& file : files_read) {
            outputs.check_input(file, file_named_by(input.source.string()));
            // Another input's output over a file this model reads: refused whichever job runs
            // first (the texture would be this run's image, or the other's output refused).
            const auto writer = settings.planned_writers->find(file);
            if (writer != settings.planned_writers->end() &&
                writer->second != input.source.string())
                throw InputError(input.source.string(),
                                 "it reads " + file.string() + ", which this batch writes as " +
                                     writer->second +
                                     "'s output: give -o a folder apart from the models");
        }
        record.triangles = scene.triangle_count();
        check_batch_limits(scene, views, settings.limits);

        double encode_ms = 0.0;
        for (const RenderArguments& view : views) {
            if (stopping(stop)) return dropped();
            // The frame's warnings (nothing in view, every triangle facing away, ...) go to the
            // record with the loader's, as render prints them.
            FrameNotes notes;
            const RenderedFrame frame =
                render_outputs(view, scene, outputs, nullptr, notes.file(), renderer);
            for (std::string& line : notes.lines()) record.warnings.push_back(std::move(line));
            record.render_ms += frame.render_ms;
            encode_ms += frame.encode_ms;
        }
        if (stopping(stop)) return dropped();
        const Clock::time_point commit_start = Clock::now();
        outputs.commit();
        record.write_ms = encode_ms + ms_since(commit_start);
        record.status = BatchStatus::Ok;
        for (const std::filesystem::path& p : planned) record.outputs.push_back(p.string());
        for (const std::filesystem::path& file : files_read) record.reads.push_back(file.string());
        return record;
    } catch (const LimitExceeded& e) {
        record.error = error_line(record.input, e.what() + limit_advice(e.limit()));
    } catch (const InputError& e) {
        record.error = error_line(record.input, e.what());
    } catch (const std::bad_alloc&) {
        record.error = error_line(record.input, "out of memory");
    } catch (const std::filesystem::filesystem_error& e) {
        record.error = error_line(record.input, e.what());
    } catch (const std::exception& e) {
        record.error = error_line(record.input, std::string("internal error: ") + e.what());
    }
    // A loader process killed by the same Ctrl-C, a frame cut short: not the file's fault.
    if (stopping(stop)) return dropped();
    record.status = BatchStatus::Error;
    return record;
}

}  // namespace zraster::cli
