// What `zraster batch` records of one input (a line of batch.jsonl, docs/batch.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace zraster::cli {

enum class BatchStatus {
    Ok,       // every output written
    Error,    // nothing written; `error` says why
    Skipped,  // every output already there, newer than the input
    Dropped,  // stopped by a signal before anything was written: not logged, a rerun does it
};

struct BatchRecord {
    std::string input;
    BatchStatus status = BatchStatus::Error;
    std::string error;                       // one line naming the input and the cause (Error only)
    std::vector<std::string> outputs;        // the files written (Ok) or found up to date (Skipped)
    std::optional<std::uint64_t> triangles;  // over the instances, when the file was loaded
    double load_ms = 0.0, render_ms = 0.0, write_ms = 0.0;
    std::vector<std::string> warnings;  // the loader's (missing textures, ...)
    std::vector<std::string> reads;     // the files the model read besides itself (Ok, Skipped)
};

// "ok", "error", "skipped", "dropped".
const char* status_name(BatchStatus status);

}  // namespace zraster::cli
