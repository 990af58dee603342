// See run_inputs.hpp.
#include "run_inputs.hpp"

namespace zraster::cli {

void check_run_inputs(const RenderArguments& a, OutputFiles& outputs) {
    outputs.check_input(a.scene, "");
    outputs.check_input(a.pvs, "--pvs");
}

}  // namespace zraster::cli
