// What earlier runs of a batch wrote, read back from its log (docs/batch.md, "Up to date"): a
// rerun skips an input only when the log's last record of it wrote exactly the outputs this run
// would write, and those outputs are newer than the input and every file its model read. Files
// at the outputs' paths that the batch did not write (the model's own texture named like its
// image) or outputs older than an edited texture are then rendered again, never taken for done.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace zraster::cli {

class BatchHistory {
  public:
    // The log's records (a missing file, a device or lines that are not records: none). Lines
    // longer than a record can be (1 MiB) are passed over unread.
    static BatchHistory read(const std::filesystem::path& log);

    // The files the input's model read, as the log's last record of `input` lists them, when
    // that record wrote (or found up to date) exactly `outputs`; null otherwise.
    const std::vector<std::string>* written(
        const std::string& input, const std::vector<std::filesystem::path>& outputs) const;

    std::size_t size() const { return entries_.size(); }

  private:
    void add(const std::string& line);  // a line of the log: a record, or passed over

    struct Entry {
        bool written = false;            // status "ok" or "skipped"
        std::uint64_t outputs_hash = 0;  // of the outputs' paths, in order
        std::vector<std::string> reads;
    };
    // Keyed by a 64-bit hash of the input's path as logged: a log of millions of inputs stays
    // small, and a collision (2^-64) would at worst skip an input whose outputs exist.
    std::unordered_map<std::uint64_t, Entry> entries_;
};

// Every output exists and was modified after the input and after every file in `reads`.
bool outputs_up_to_date(const std::filesystem::path& input,
                        const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::string>& reads);

}  // namespace zraster::cli
