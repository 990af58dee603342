// `zraster batch` runs can be repeated and split: a rerun skips what is up to date and redoes
// what is not (--force: everything); SIGTERM mid-batch leaves whole files only and a rerun
// finishes the rest; --shard K/N for K = 0..N-1 renders every input exactly once.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include "batch_test_support.hpp"

extern char** environ;

namespace zraster::test {
namespace {

std::map<std::string, std::filesystem::file_time_type> modification_times(
    const std::filesystem::path& dir) {
    std::map<std::string, std::filesystem::file_time_type> times;
    for (const std::string& file : files_under(dir))
        if (file != "batch.jsonl") times[file] = std::filesystem::last_write_time(dir / file);
    return times;
}

std::map<std::string, int> status_counts(const std::vector<nlohmann::json>& records) {
    std::map<std::string, int> counts;
    for (const auto& record : records) ++counts[record.at("status").get<std::string>()];
    return counts;
}

TEST(BatchResume, RerunSkipsUpToDateInputsAndForceRedoesThem) {
    const auto dir = temp_dir("batch-rerun");
    for (int i = 0; i < 4; ++i)
        write_sphere_obj(dir / "in" / ("s" + std::to_string(i) + ".obj"), 10, i);
    const std::string batch = "batch in -o out --size 32x32 --normal --progress none";
    ASSERT_EQ(run_zraster(batch, dir).exit_code, 0);
    ASSERT_EQ(read_log(dir / "out" / "batch.jsonl").size(), 4u);
    const auto first = modification_times(dir / "out");
    ASSERT_EQ(first.size(), 8u);

    // Everything up to date: all skipped, nothing rewritten, the log grows by one record each.
    const CommandResult again = run_zraster(batch, dir);
    EXPECT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("0 ok, 0 failed, 4 skipped"), std::string::npos) << again.output;
    auto log = read_log(dir / "out" / "batch.jsonl");
    ASSERT_EQ(log.size(), 8u);
    EXPECT_EQ(status_counts({log.begin() + 4, log.end()})["skipped"], 4);
    for (auto it = log.begin() + 4; it != log.end(); ++it) EXPECT_EQ(it->at("outputs").size(), 2u);
    EXPECT_EQ(modification_times(dir / "out"), first);

    // An input changed after its outputs, and an output removed: those two are redone.
    std::filesystem::last_write_time(
        dir / "in" / "s1.obj",
        std::filesystem::last_write_time(dir / "out" / "s1.png") + std::chrono::seconds(10));
    std::filesystem::remove(dir / "out" / "s2_normal.png");
    const CommandResult partial = run_zraster(batch, dir);
    EXPECT_EQ(partial.exit_code, 0) << partial.output;
    log = read_log(dir / "out" / "batch.jsonl");
    ASSERT_EQ(log.size(), 12u);
    const auto third = records_by_input(log);
    EXPECT_EQ(third.at("in/s0.obj").at("status"), "skipped");
    EXPECT_EQ(third.at("in/s1.obj").at("status"), "ok");
    EXPECT_EQ(third.at("in/s2.obj").at("status"), "ok");
    EXPECT_EQ(third.at("in/s3.obj").at("status"), "skipped");
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "s2_normal.png"));

    // --force: every input rendered again, every output rewritten.
    const auto before = modification_times(dir / "out");
    const CommandResult forced = run_zraster(batch + " --force", dir);
    EXPECT_EQ(forced.exit_code, 0) << forced.output;
    EXPECT_NE(forced.output.find("4 ok, 0 failed, 0 skipped"), std::string::npos) << forced.output;
    for (const auto& [file, time] : modification_times(dir / "out"))
        EXPECT_GT(time, before.at(file)) << file;
}

// Up to date means "written by an earlier run, and nothing it was made from changed since": the
// log's records say which outputs a run wrote and which files each model read.
TEST(BatchResume, OnlyOutputsTheLogRecordsAreUpToDateAndTheirModelsFilesCount) {
    const auto dir = temp_dir("batch-rerun-reads");
    ASSERT_EQ(run_zraster("render builtin:cube --size 4x4 -o tex.png", dir).exit_code, 0);
    write_text(dir / "in" / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd ../tex.png\n");
    write_text(dir / "in" / "m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    write_sphere_obj(dir / "in" / "s.obj", 8, 1);
    const std::string batch =
        "batch in -o out --size 16x16 --progress none --allow-outside-references";
    const CommandResult first = run_zraster(batch, dir);
    ASSERT_EQ(first.exit_code, 0) << first.output;
    auto records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    const std::string texture = std::filesystem::canonical(dir / "tex.png").string();
    EXPECT_EQ(records.at("in/m.obj").at("reads"),
              nlohmann::json({std::filesystem::canonical(dir / "in" / "m.mtl").string(), texture}));
    EXPECT_EQ(records.at("in/s.obj").at("reads"), nlohmann::json::array());

    // The texture edited after the images (the image made older than it): its model is
    // rendered again, the other skipped.
    std::filesystem::last_write_time(
        dir / "out" / "m.png",
        std::filesystem::last_write_time(dir / "tex.png") - std::chrono::seconds(10));
    const CommandResult edited = run_zraster(batch, dir);
    EXPECT_NE(edited.output.find("1 ok, 0 failed, 1 skipped"), std::string::npos) << edited.output;
    records = records_by_input(read_log(dir / "out" / "batch.jsonl"));
    EXPECT_EQ(records.at("in/m.obj").at("status"), "ok");
    EXPECT_EQ(records.at("in/s.obj").at("status"), "skipped");
    // A skipped record carries the reads on, for the run after it.
    EXPECT_EQ(records.at("in/s.obj").at("reads"), nlohmann::json::array());
    const CommandResult again = run_zraster(batch, dir);
    EXPECT_NE(again.output.find("0 ok, 0 failed, 2 skipped"), std::string::npos) << again.output;

    // Without the log nothing is known to be written: every input is rendered.
    std::filesystem::remove(dir / "out" / "batch.jsonl");
    const CommandResult no_log = run_zraster(batch, dir);
    EXPECT_NE(no_log.output.find("2 ok, 0 failed, 0 skipped"), std::string::npos) << no_log.output;
}

// A folder made where an output was is not an output: the rerun renders the file (and fails
// writing over the folder) instead of skipping it.
TEST(BatchResume, AFolderWhereAnOutputWasIsNotUpToDate) {
    const auto dir = temp_dir("batch-rerun-folder");
    write_text(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    ASSERT_EQ(run_zraster("batch m.obj -o out --size 8x8 --progress none", dir).exit_code, 0);
    std::filesystem::remove(dir / "out" / "m.png");
    std::filesystem::create_directory(dir / "out" / "m.png");
    const CommandResult r = run_zraster("batch m.obj -o out --size 8x8 --progress none", dir);
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("0 ok, 1 failed, 0 skipped"), std::string::npos) << r.output;
}

TEST(BatchResume, AFileTheBatchDidNotWriteIsNeverTakenForAnOutput) {
    // m.obj's image would be ./m.png, which is its own texture: refused, and refused again on
    // every rerun however new the texture is (it was never an output).
    const auto dir = temp_dir("batch-rerun-not-written");
    ASSERT_EQ(run_zraster("render builtin:cube --size 4x4 -o m.png", dir).exit_code, 0);
    write_text(dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd m.png\n");
    write_text(dir / "m.obj",
               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    const std::string texture = read_bytes(dir / "m.png");
    for (int run = 0; run < 2; ++run) {
        SCOPED_TRACE(run);
        std::filesystem::last_write_time(
            dir / "m.png",
            std::filesystem::last_write_time(dir / "m.obj") + std::chrono::seconds(10));
        const CommandResult r = run_zraster("batch m.obj -o . --size 8x8 --progress none", dir);
        EXPECT_EQ(r.exit_code, 3) << r.output;
        EXPECT_NE(r.output.find("0 ok, 1 failed, 0 skipped"), std::string::npos) << r.output;
        const auto log = read_log(dir / "batch.jsonl");
        ASSERT_EQ(log.size(), std::size_t(run + 1));
        EXPECT_EQ(log.back().at("status"), "error");
        EXPECT_NE(log.back().at("error").get<std::string>().find("is the same file as the input"),
                  std::string::npos);
        EXPECT_EQ(read_bytes(dir / "m.png"), texture);
    }
    // A log line that is not a record (or a line of megabytes) is passed over.
    write_text(dir / "batch.jsonl", read_bytes(dir / "batch.jsonl") + "{\"input\": 3}\nnot json\n" +
                                        "{" + std::string(3 << 20, ' ') + "}\n");
    const CommandResult r = run_zraster("batch m.obj -o . --size 8x8 --progress none", dir);
    EXPECT_EQ(r.exit_code, 3) << r.output;
}

// Starts `zraster ARGUMENTS` in `cwd` with its output to `output_file`; returns its pid.
pid_t spawn_zraster(const std::string& arguments, const std::filesystem::path& cwd,
                    const std::filesystem::path& output_file) {
    const std::string line = "cd '" + cwd.string() + "' && exec " + zraster_command() + " " +
                             arguments + " >'" + output_file.string() + "' 2>&1 </dev/null";
    const char* argv[] = {"/bin/sh", "-c", line.c_str(), nullptr};
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    return pid;
}

std::size_t line_count(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    return lines;
}

TEST(BatchResume, SigtermLeavesWholeFilesOnlyAndARerunFinishes) {
    const auto dir = temp_dir("batch-sigterm");
    constexpr int kFiles = 120;
    for (int i = 0; i < kFiles; ++i)
        write_sphere_obj(dir / "in" / ("s" + std::to_string(i) + ".obj"), 100, i);
    const std::string batch =
        "batch in -o out --size 256x256 --depth npy --jobs 2 --threads 1 --progress none";
    const pid_t pid = spawn_zraster(batch, dir, dir / "first.txt");
    ASSERT_GT(pid, 0);
    // Once the first file is logged, ask it to stop (it has most of its files left then).
    int status = 0;
    bool ended = false;
    while (!ended && line_count(dir / "out" / "batch.jsonl") == 0) {
        ended = waitpid(pid, &status, WNOHANG) == pid;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (ended) GTEST_SKIP() << "the batch of " << kFiles << " files ended before a record was seen";
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    const std::string first = read_bytes(dir / "first.txt");
    ASSERT_TRUE(WIFEXITED(status)) << first;
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << first;
    EXPECT_NE(first.find("stopped by SIGTERM"), std::string::npos) << first;

    // Whole lines for the inputs finished, every one of them ok; exactly their files on disk.
    const auto log = read_log(dir / "out" / "batch.jsonl");
    ASSERT_GE(log.size(), 1u);
    ASSERT_LT(log.size(), std::size_t(kFiles));
    std::set<std::string> logged;
    for (const auto& record : log) {
        EXPECT_EQ(record.at("status"), "ok") << record.dump();
        for (const auto& output : record.at("outputs")) logged.insert(output.get<std::string>());
    }
    std::set<std::string> on_disk;
    for (const std::string& file : files_under(dir / "out"))
        if (file != "batch.jsonl") on_disk.insert("out/" + file);
    EXPECT_EQ(on_disk, logged);

    // The rerun renders the rest and skips what the first run finished.
    const CommandResult rerun = run_zraster(batch, dir);
    EXPECT_EQ(rerun.exit_code, 0) << rerun.output;
    const auto second = read_log(dir / "out" / "batch.jsonl");
    const auto counts = status_counts({second.begin() + std::ptrdiff_t(log.size()), second.end()});
    EXPECT_EQ(counts.at("skipped"), int(log.size()));
    EXPECT_EQ(counts.at("ok"), kFiles - int(log.size()));
    EXPECT_EQ(records_by_input(second).size(), std::size_t(kFiles));

    // The files the stopped run wrote are whole: the same bytes as a run never stopped.
    const CommandResult reference = run_zraster(
        "batch in -o reference --size 256x256 --depth npy --jobs 2 --progress none", dir);
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    std::set<std::string> files = files_under(dir / "out");
    EXPECT_EQ(files, files_under(dir / "reference"));
    files.erase("batch.jsonl");
    EXPECT_EQ(files.size(), std::size_t(2 * kFiles));
    for (const std::string& file : files)
        EXPECT_TRUE(read_bytes(dir / "out" / file) == read_bytes(dir / "reference" / file)) << file;
}

std::uint64_t fnv1a64(const std::string& text) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    return hash;
}

TEST(BatchResume, ShardsCoverEveryInputExactlyOnce) {
    const auto dir = temp_dir("batch-shards");
    std::set<std::string> all;
    for (int i = 0; i < 24; ++i) {
        const std::string name = (i % 2 ? "a/m" : "b/c/m") + std::to_string(i);
        write_sphere_obj(dir / "in" / (name + ".obj"), 6, i);
        all.insert("in/" + name + ".obj");
    }
    for (const int n : {1, 2, 3, 5}) {
        SCOPED_TRACE(n);
        std::map<std::string, int> rendered;
        for (int k = 0; k < n; ++k) {
            const std::string out = "out" + std::to_string(n);
            const CommandResult r =
                run_zraster("batch in -o " + out + " --size 16x16 --progress none --log " + out +
                                "/shard" + std::to_string(k) + ".jsonl --shard " +
                                std::to_string(k) + "/" + std::to_string(n),
                            dir);
            ASSERT_EQ(r.exit_code, 0) << r.output;
            for (const auto& record :
                 read_log(dir / out / ("shard" + std::to_string(k) + ".jsonl"))) {
                EXPECT_EQ(record.at("status"), "ok");
                const std::string input = record.at("input").get<std::string>();
                ++rendered[input];
                // The documented rule: FNV-1a 64 of the output path under OUTDIR, no extension.
                const std::string stem = input.substr(3, input.size() - 7);
                EXPECT_EQ(fnv1a64(stem) % std::uint64_t(n), std::uint64_t(k)) << input;
            }
        }
        EXPECT_EQ(rendered.size(), all.size());
        for (const std::string& input : all) EXPECT_EQ(rendered[input], 1) << input;
    }
}

}  // namespace
}  // namespace zraster::test
