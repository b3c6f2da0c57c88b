#include "lube/LargeArrayAllocator.hpp"

#include <cstdlib>
#include <mutex>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace flexehd::lube::detail {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeMin = std::size_t{1} << 20;
// Enough for every large array of a cold 512×1024 solve (~100 bytes per node) and its
// ReynoldsSystem; beyond it the oldest freed blocks go back to the system.
constexpr std::size_t kCacheLimit = std::size_t{128} << 20;

std::size_t padded(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

// Freed huge-page blocks, oldest first. Reuse needs the same padded size: the sizes recur
// exactly (one grid, one hierarchy), and a block is returned with the size it was asked for.
struct BlockCache {
    std::mutex mutex;
    std::vector<std::pair<void*, std::size_t>> blocks;
    std::size_t bytes = 0;
};

// Never destroyed: arrays in static objects may be freed after every function-local static is
// gone; the blocks still held at exit go back to the system with the process.
BlockCache& cache() {
    static BlockCache* c = new BlockCache;
    return *c;
}
}  // namespace

void* allocateLarge(std::size_t bytes) {
    if (bytes < kLargeMin) return ::operator new(bytes);
    const std::size_t size = padded(bytes);
    {
        BlockCache& c = cache();
        std::lock_guard<std::mutex> lock(c.mutex);
        for (std::size_t i = c.blocks.size(); i-- > 0;)  // the most recently freed first
            if (c.blocks[i].second == size) {
                void* p = c.blocks[i].first;
                c.blocks.erase(c.blocks.begin() + static_cast<std::ptrdiff_t>(i));
                c.bytes -= size;
                return p;
            }
    }
    void* p = std::aligned_alloc(kHugePage, size);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
    return p;
}

void deallocateLarge(void* p, std::size_t bytes) noexcept {
    if (bytes < kLargeMin) {
        ::operator delete(p);
        return;
    }
    const std::size_t size = padded(bytes);
    if (size > kCacheLimit) {
        std::free(p);
        return;
    }
    BlockCache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    try {
        c.blocks.emplace_back(p, size);
    } catch (...) {  // no room to remember it: give it back
        std::free(p);
        return;
    }
    c.bytes += size;
    std::size_t evict = 0;
    for (std::size_t held = c.bytes; held > kCacheLimit; ++evict) held -= c.blocks[evict].second;
    for (std::size_t i = 0; i < evict; ++i) {
        std::free(c.blocks[i].first);
        c.bytes -= c.blocks[i].second;
    }
    c.blocks.erase(c.blocks.begin(), c.blocks.begin() + static_cast<std::ptrdiff_t>(evict));
}

std::size_t largeCacheBytes() {
    BlockCache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    return c.bytes;
}

std::size_t largeCacheLimit() { return kCacheLimit; }

}  // namespace flexehd::lube::detail

namespace flexehd::lube {

void retainFreedHeapMemory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
}

}  // namespace flexehd::lube
