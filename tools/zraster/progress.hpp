// Progress of long object-space work (painter's, BSP, Warnock), shown on stderr.
#pragma once
#include <zraster/render.hpp>

namespace zraster::cli {

// The command's reporter (one per process): when stderr is a terminal, silent for the first two
// seconds of a run, then a line on stderr at most every two seconds, and when the stage changes;
// silent when stderr is not a terminal (a refusal stays one line for the programs reading it).
ProgressReporter* stderr_progress();

}  // namespace zraster::cli
