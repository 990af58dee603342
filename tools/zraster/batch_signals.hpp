// SIGINT and SIGTERM ask `zraster batch` to stop: while a StopOnSignals lives, the first of them
// sets the flag that the jobs read (they then finish or drop the files in flight and write no
// partial output); a second one ends the process at once, as without the handler.
#pragma once
#include <atomic>

namespace zraster::cli {

class StopOnSignals {
  public:
    StopOnSignals();   // installs the handlers
    ~StopOnSignals();  // puts the previous ones back
    StopOnSignals(const StopOnSignals&) = delete;
    StopOnSignals& operator=(const StopOnSignals&) = delete;

    // Set by the first signal; may also be set by the program itself.
    std::atomic<bool>& stop();
    // The signal that set it (SIGINT or SIGTERM), 0 when none did.
    int signal() const;
};

}  // namespace zraster::cli
