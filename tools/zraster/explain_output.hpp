// What `zraster explain` writes into its folder: pictures (PNG, SVG, animated PNG) and an
// index.html naming what each shows. Everything is written together at the end, or nothing
// (OutputFiles).
#pragma once
#include <zraster/output_files.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "figure.hpp"
#include "rgba_image.hpp"

namespace zraster::cli {

class ExplainOutput {
  public:
    // Throws InputError("-o", ...) when `folder` cannot be one. The folder (and missing parents)
    // is made by commit(), after the work: a run refused, failed or killed leaves nothing.
    ExplainOutput(std::filesystem::path folder, std::string title, std::string introduction);
    ~ExplainOutput();
    ExplainOutput(const ExplainOutput&) = delete;
    ExplainOutput& operator=(const ExplainOutput&) = delete;

    // A file the run reads (the model): no picture may replace it (OutputFiles::check_input).
    void check_input(const std::filesystem::path& path, const std::string& what);

    void still(const std::string& name, const RgbaImage& image, const std::string& caption);
    // name.svg, and name.png rasterized from the same figure.
    void figure(const std::string& name, const Figure& figure, const std::string& caption);
    // name.svg only (diagrams too large for the bitmap font).
    void svg(const std::string& name, const std::string& text, const std::string& caption);
    // name.png, an animated PNG of the frames (each shown delay_ms).
    void animation(const std::string& name, const std::vector<RgbaImage>& frames, int delay_ms,
                   const std::string& caption);
    // Makes the folder and writes every file and index.html (the folders it made are removed
    // again when the writing fails).
    void commit();
    // The files written (or to be written), index.html last.
    std::vector<std::string> file_names() const;

  private:
    void add(const std::string& file, std::vector<std::uint8_t> bytes);
    void make_folder();
    struct Entry {
        std::string file, caption;
    };
    std::filesystem::path folder_;
    std::string title_, introduction_;
    std::vector<Entry> entries_;
    std::vector<std::string> files_;
    // The encoded files, checked and handed to outputs_ once the folder exists (commit()).
    std::vector<std::pair<std::string, std::vector<std::uint8_t>>> pending_;
    OutputFiles outputs_;
    std::vector<std::filesystem::path> created_;  // deepest first
    bool committed_ = false;
};

}  // namespace zraster::cli
