// `zraster view` in a build configured without SDL2: a clear refusal.
#include <zraster/error.hpp>

#include "view_window.hpp"

namespace zraster::cli {

ViewSummary run_view_window(ViewSetup&) {
    throw InputError("view",
                     "this zraster was built without SDL2 (install libsdl2-dev and "
                     "configure again)");
}

}  // namespace zraster::cli
