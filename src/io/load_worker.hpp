// Assimp in a child process (LoadIsolation::WorkerProcess, include/zraster/load.hpp): a crash,
// hang or runaway allocation inside the importer ends the child, not the caller.
#pragma once
#include <zraster/load.hpp>
#include <zraster/scene.hpp>

#include "io/loaded_scene.hpp"
#include "io/obj_material_libraries.hpp"

#include <filesystem>

namespace zraster::io {

// Runs import_with_assimp(path, options, true, obj_libraries) in a forked child under the limits
// of `options` (worker_timeout_for, worker_memory_for) and returns the validated scene it sends
// back. Throws InputError naming the file for a bad file and for a child that crashed or was
// killed; LimitExceeded for one that took longer than its time (worker_timeout_seconds) or ran
// out of its memory (max_geometry_bytes, or worker_memory_bytes when that was set).
LoadedScene load_in_worker(const std::filesystem::path& path, const LoadOptions& options,
                           const ObjMaterialLibraries* obj_libraries = nullptr);

// Tests only: a function the child calls before importing (to make it crash, hang or allocate
// without bound); null (the default) for none. Not thread-safe; set it before loading.
using WorkerTestHook = void (*)();
void set_worker_test_hook(WorkerTestHook hook);

}  // namespace zraster::io
