// The command-line tool's global operator new: blocks of 4 MiB and more (images, files read,
// vertex arrays, bins) come 2 MiB-aligned and advised for transparent huge pages, so huge pages
// back them from their first byte to their last. On this project's benchmark VM a page fault
// costs microseconds, and one `zraster render` of the bunny touched about 13,600 small pages.
// The library leaves allocation to the application that embeds it; this is the tool's choice.
#include <cstdlib>
#include <new>

#include "memory/huge_pages.hpp"

// Sanitizer runtimes bring their own operator new (to track every block): keep theirs.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define ZRASTER_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define ZRASTER_SANITIZER_ALLOCATOR 1
#endif
#endif

#if !defined(ZRASTER_SANITIZER_ALLOCATOR)

namespace {

constexpr std::size_t kLargeBlock = std::size_t{4} << 20;

void* allocate(std::size_t bytes) noexcept {
    using zraster::memory::kHugePageBytes;
    if (bytes >= kLargeBlock && bytes <= SIZE_MAX - kHugePageBytes) {
        const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        if (void* p = std::aligned_alloc(kHugePageBytes, rounded)) {
            zraster::memory::advise_huge_pages(p, rounded);
            return p;
        }
    }
    return std::malloc(bytes == 0 ? 1 : bytes);
}

}  // namespace

void* operator new(std::size_t bytes) {
    if (void* p = allocate(bytes)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t bytes) {
    if (void* p = allocate(bytes)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
    return allocate(bytes);
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
    return allocate(bytes);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}

#endif  // !ZRASTER_SANITIZER_ALLOCATOR
