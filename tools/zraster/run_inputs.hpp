// The files a run of the command reads, made known to its OutputFiles so that no output replaces
// one of them (`zraster render m.ply --points-out m.ply` would lose the model).
#pragma once
#include <zraster/output_files.hpp>

#include "render_arguments.hpp"

namespace zraster::cli {

// The model (a procedural spec names no file and is passed over) and --pvs, through
// OutputFiles::check_input. Throws InputError naming an output that is one of them.
void check_run_inputs(const RenderArguments& arguments, OutputFiles& outputs);

}  // namespace zraster::cli
