// LargeArrayAllocator (lube/LargeArrayAllocator.hpp): blocks of at least 1 MiB are 2 MiB aligned,
// a freed block is handed out again for the next request of the same padded size (what saves a
// repeated cold solve its page faults), a different size gets a different block, and the blocks
// kept for reuse never exceed the stated limit.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "lube/LargeArrayAllocator.hpp"

using namespace flexehd::lube;

namespace {
constexpr std::size_t kMiB = std::size_t{1} << 20;
std::uintptr_t address(const LargeVector<double>& v) { return reinterpret_cast<std::uintptr_t>(v.data()); }
}  // namespace

TEST(LargeArrayAllocator, FreedBlockIsReusedForTheSameSize) {
    const std::size_t n = 3 * kMiB / sizeof(double);  // 3 MiB → two 2 MiB pages
    std::uintptr_t first = 0;
    {
        LargeVector<double> a(n);
        first = address(a);
        EXPECT_EQ(first % (2 * kMiB), 0u);
        a[0] = a[n - 1] = 42.0;
    }
    LargeVector<double> b(n - 1000);  // same padded size
    EXPECT_EQ(address(b), first);
    LargeVector<double> c(5 * kMiB / sizeof(double));  // larger: not the (taken) block above
    EXPECT_NE(address(c), first);
    EXPECT_EQ(address(c) % (2 * kMiB), 0u);
}

TEST(LargeArrayAllocator, CacheStaysWithinItsLimit) {
    const std::size_t n = 6 * kMiB / sizeof(double);
    const std::size_t count = detail::largeCacheLimit() / (6 * kMiB) + 8;  // more than it may keep
    {
        std::vector<LargeVector<double>> blocks;
        for (std::size_t i = 0; i < count; ++i) blocks.emplace_back(n);
    }  // all freed
    EXPECT_GT(detail::largeCacheBytes(), 0u);
    EXPECT_LE(detail::largeCacheBytes(), detail::largeCacheLimit());
    // Small blocks take the ordinary heap and are not cached.
    const std::size_t before = detail::largeCacheBytes();
    { LargeVector<double> small(1000); }
    EXPECT_EQ(detail::largeCacheBytes(), before);
}
