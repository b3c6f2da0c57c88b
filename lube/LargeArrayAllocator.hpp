#pragma once
// LargeArrayAllocator: storage for the per-node arrays of the film solvers (stencils, multigrid
// work vectors). A cold solve touches ~100 bytes of fresh memory per node; with 4 KiB pages every
// page costs a page fault, which on a virtual machine can cost as much as the arithmetic of the
// whole solve (docs/lube.md §7). Blocks of at least 1 MiB are therefore 2 MiB aligned, padded to
// whole 2 MiB pages and advised for transparent huge pages (Linux madvise(MADV_HUGEPAGE); a no-op
// where THP is off), and freed blocks are kept for reuse (a bounded cache), so that repeated
// solves of one grid size do not fault and zero-fill fresh pages each time. Smaller blocks come
// from operator new. Elements are default-initialised: resize() does not zero doubles (assign()
// does) — fill them before use; a reused block holds the values of its previous owner.
#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace flexehd::lube {

namespace detail {
void* allocateLarge(std::size_t bytes);
void deallocateLarge(void* p, std::size_t bytes) noexcept;
/// Bytes held by freed blocks kept for reuse (at most largeCacheLimit()).
std::size_t largeCacheBytes();
std::size_t largeCacheLimit();
}  // namespace detail

template <class T>
struct LargeArrayAllocator {
    using value_type = T;
    LargeArrayAllocator() = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(detail::allocateLarge(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { detail::deallocateLarge(p, n * sizeof(T)); }
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;  // default-initialisation: no zero fill
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const LargeArrayAllocator<U>&) const noexcept { return true; }
};
template <class T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;

/// For programs that run many solves (the flexehd command line, the benchmarks): a process-wide
/// glibc setting (a no-op elsewhere) that keeps freed blocks of up to 32 MiB in the heap instead
/// of unmapping them, and does not trim the heap below 512 MiB. Every solve allocates and frees
/// vectors of megabytes (pressures, right-hand sides, the start of a cold solve, the coupled
/// Newton method's factorizations); handed back to the system each time, every touch of their
/// pages is a page fault again (40 % of a co-simulation's run time, docs/coupling.md §4; ~5 % of a
/// cold 256×512 film solve, docs/lube.md §7). Call once, early in main().
void retainFreedHeapMemory();

}  // namespace flexehd::lube
