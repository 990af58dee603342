// Large buffers on transparent huge pages. A 1080p frame's color and depth targets are 4096
// small pages; each first touch is a page fault, and in a virtual machine the faults of a
// one-shot render of a small mesh cost more than rendering it. With THP in "madvise" mode
// (Debian's default) the kernel backs a range with 2 MiB pages only when asked, before the
// range is first touched.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace zraster::memory {

// Below this a buffer cannot hold a whole huge page.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// Advises the kernel to use huge pages for [data, data + bytes) (the whole pages inside it).
// A hint: failures (no THP, another OS) change nothing but speed.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes < kHugePageBytes) return;
    constexpr std::uintptr_t kPage = 4096;
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

// v.resize(n), with new storage (when v must grow) advised for huge pages before the resize
// touches it.
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n) {
    if (n > v.capacity() && v.empty()) {
        v.reserve(n);
        advise_huge_pages(v.data(), n * sizeof(T));
    }
    v.resize(n);
}

// v.reserve(n), the new storage advised for huge pages (for a vector filled by appending).
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t n) {
    if (n > v.capacity() && v.empty()) {
        v.reserve(n);
        advise_huge_pages(v.data(), n * sizeof(T));
    }
}

}  // namespace zraster::memory
