// See batch_signals.hpp.
#include "batch_signals.hpp"

#include <csignal>

namespace zraster::cli {
namespace {

std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_previous_int {
}, g_previous_term{};

static_assert(std::atomic<bool>::is_always_lock_free, "the handler stores to it");

extern "C" void on_stop_signal(int sig) {
    if (g_signal != 0) {
        // The second request: no more waiting for the files in flight.
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    g_signal = sig;
    g_stop.store(true);
}

}  // namespace

StopOnSignals::StopOnSignals() {
    g_stop.store(false);
    g_signal = 0;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and waits go on; the jobs poll the flag
    sigaction(SIGINT, &action, &g_previous_int);
    sigaction(SIGTERM, &action, &g_previous_term);
}

StopOnSignals::~StopOnSignals() {
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
}

std::atomic<bool>& StopOnSignals::stop() {
    return g_stop;
}

int StopOnSignals::signal() const {
    return g_signal;
}

}  // namespace zraster::cli
