// The JSON Lines log of `zraster batch` (OUTDIR/batch.jsonl by default; the record schema is in
// docs/batch.md): one line per input, appended as each input ends, so that a batch stopped at any
// point leaves whole lines for the inputs it finished.
#pragma once
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "batch_record.hpp"

namespace zraster::cli {

// The record as one line of JSON, without the newline. Fields in this order: input, status,
// error (null unless status is "error"), outputs, triangles (null when the file was not loaded),
// load_ms, render_ms, write_ms, warnings, reads. Text that is not UTF-8 has its bad bytes replaced.
std::string record_json(const BatchRecord& record);

class BatchLog {
  public:
    // Opens `path` for appending (created when missing). Throws InputError naming it.
    // `opened`: the file already open for writing (a FIFO the plan opened), written instead.
    explicit BatchLog(const std::filesystem::path& path,
                      std::shared_ptr<const int> opened = nullptr);
    ~BatchLog();
    BatchLog(const BatchLog&) = delete;
    BatchLog& operator=(const BatchLog&) = delete;

    // Appends the record's line with one write(2) (O_APPEND: whole lines even when several
    // processes share the file on a local file system). Thread-safe. Throws InputError naming
    // the log when the write fails.
    void append(const BatchRecord& record);

    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    std::shared_ptr<const int> opened_;
    int fd_ = -1;
    std::mutex mutex_;
};

}  // namespace zraster::cli
