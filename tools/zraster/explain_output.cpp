// The explain folder and its index.
#include "explain_output.hpp"

#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <fmt/format.h>

#include <algorithm>

#include <unistd.h>

#include "apng_encode.hpp"

namespace zraster::cli {
namespace {

std::vector<std::uint8_t> png_of(const RgbaImage& image) {
    return encode_png8(image.width, image.height, 3, rgb_bytes(image));
}

}  // namespace

ExplainOutput::ExplainOutput(std::filesystem::path folder, std::string title,
                             std::string introduction)
    : folder_(std::move(folder)), title_(std::move(title)), introduction_(std::move(introduction)) {
    std::error_code error;
    if (std::filesystem::exists(folder_, error) && !std::filesystem::is_directory(folder_, error))
        throw InputError("-o", folder_.string() + " exists and is not a folder");
    // What making it would meet, told before the work: the nearest existing ancestor must be a
    // folder this process may write into.
    std::filesystem::path existing = folder_;
    while (!existing.empty() && !std::filesystem::exists(existing, error) &&
           existing != existing.parent_path())
        existing = existing.parent_path();
    if (existing.empty()) existing = ".";
    if (existing != folder_ || !std::filesystem::exists(folder_, error)) {
        const char* cause = !std::filesystem::is_directory(existing, error) ? "Not a directory"
                            : ::access(existing.c_str(), W_OK | X_OK) != 0  ? "Permission denied"
                                                                            : nullptr;
        if (cause != nullptr)
            throw InputError("-o", "cannot make the folder " + folder_.string() + ": " + cause);
    }
}

void ExplainOutput::make_folder() {
    std::error_code error;
    for (std::filesystem::path p = folder_; !p.empty() && !std::filesystem::exists(p, error);
         p = p.parent_path()) {
        created_.push_back(p);
        if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(folder_, error);
    if (error) {
        std::error_code ignored;
        for (const std::filesystem::path& p : created_) std::filesystem::remove(p, ignored);
        created_.clear();
        throw InputError("-o",
                         "cannot make the folder " + folder_.string() + ": " + error.message());
    }
}

ExplainOutput::~ExplainOutput() {
    if (committed_) return;
    // Only folders left empty go (remove() refuses others): those this run made.
    std::error_code error;
    for (const std::filesystem::path& p : created_) std::filesystem::remove(p, error);
}

void ExplainOutput::check_input(const std::filesystem::path& path, const std::string& what) {
    outputs_.check_input(path, what);
}

void ExplainOutput::add(const std::string& file, std::vector<std::uint8_t> bytes) {
    pending_.emplace_back(file, std::move(bytes));
    files_.push_back(file);
}

void ExplainOutput::still(const std::string& name, const RgbaImage& image,
                          const std::string& caption) {
    add(name + ".png", png_of(image));
    entries_.push_back({name + ".png", caption});
}

void ExplainOutput::figure(const std::string& name, const Figure& figure,
                           const std::string& caption) {
    const std::string text = figure.svg();
    add(name + ".svg", std::vector<std::uint8_t>(text.begin(), text.end()));
    add(name + ".png", png_of(figure.raster()));
    entries_.push_back({name + ".svg", caption});
}

void ExplainOutput::svg(const std::string& name, const std::string& text,
                        const std::string& caption) {
    add(name + ".svg", std::vector<std::uint8_t>(text.begin(), text.end()));
    entries_.push_back({name + ".svg", caption});
}

void ExplainOutput::animation(const std::string& name, const std::vector<RgbaImage>& frames,
                              int delay_ms, const std::string& caption) {
    // Captions may wrap to different heights: every frame on a canvas of the largest size.
    int width = 0, height = 0;
    for (const RgbaImage& f : frames) {
        width = std::max(width, f.width);
        height = std::max(height, f.height);
    }
    std::vector<RgbaImage> padded;
    for (const RgbaImage& f : frames) {
        RgbaImage canvas(width, height, Rgba{255, 255, 255, 255});
        paste(canvas, f, 0, 0);
        padded.push_back(std::move(canvas));
    }
    add(name + ".png", encode_apng(padded, delay_ms));
    entries_.push_back({name + ".png", caption + " (animated PNG)"});
}

std::vector<std::string> ExplainOutput::file_names() const {
    std::vector<std::string> names = files_;
    names.push_back("index.html");
    return names;
}

void ExplainOutput::commit() {
    std::string html = fmt::format(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{0}</title>\n"
        "<style>body{{font-family:sans-serif;max-width:60em;margin:2em auto}}"
        "figure{{margin:2em 0}}img{{max-width:100%;border:1px solid #ccc}}</style></head>\n"
        "<body>\n<h1>{0}</h1>\n<p>{1}</p>\n",
        xml_escape(title_), xml_escape(introduction_));
    for (const Entry& e : entries_)
        html += fmt::format(
            "<figure><img src=\"{0}\" alt=\"{0}\"><figcaption><code>{0}</code>: "
            "{1}</figcaption></figure>\n",
            e.file, xml_escape(e.caption));
    html += "</body></html>\n";
    add("index.html", std::vector<std::uint8_t>(html.begin(), html.end()));
    files_.pop_back();  // index.html is listed last by file_names()
    make_folder();
    for (auto& [file, bytes] : pending_) {
        outputs_.check(folder_ / file, "-o");
        outputs_.add(folder_ / file, std::move(bytes));
    }
    pending_.clear();
    outputs_.commit();
    committed_ = true;
}

}  // namespace zraster::cli
