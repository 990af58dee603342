// Progress of long object-space work (painter's, BSP, Warnock), shown on stderr.
#pragma once
#include <zraster/render.hpp>

namespace zraster::cli {

// The command's reporter (one per process): silent for the first two seconds of a run, then a
// line on stderr at most every two seconds, and when the stage changes.
ProgressReporter* stderr_progress();

}  // namespace zraster::cli
