// How much memory this process may use, as the operating system says: a budget raised past it
// is refused naming the budget before the allocation the system would refuse ("out of memory"
// after minutes of work, naming nothing).
#pragma once
#include <cstdint>

namespace zraster::platform {

// The least of the machine's physical memory and the process's address-space and data limits
// (RLIMIT_AS, RLIMIT_DATA: prlimit, ulimit -v), in bytes. Asked afresh on each call.
std::uint64_t usable_memory_bytes();

}  // namespace zraster::platform
