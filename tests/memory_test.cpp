// The render's large arrays (renderer/src/base/memory.h): blocks freed by one render are what the next one
// gets, whatever the element size, and what is kept stays bounded.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "base/memory.h"

namespace {

using raster::detail::PodArray;

struct Record {  // 88 bytes, like a triangle record: 2 MiB blocks hold no whole number of them
  std::array<std::uint8_t, 88> bytes;
};

// A large array's block, once freed, is the one the next array of that size gets: its pages were touched
// already (the point of keeping it). An element size that does not divide the block must not lose it.
TEST(Memory, AFreedLargeBlockIsReusedWhateverTheElementSize) {
  constexpr std::size_t kCount = 100'000;  // 8.8 MB
  const void* first = nullptr;
  {
    PodArray<Record> a;
    a.resize_uninitialized(kCount);
    a[kCount - 1].bytes[0] = 1;
    first = a.data();
  }
  PodArray<Record> b;
  b.resize_uninitialized(kCount);
  EXPECT_EQ(b.data(), first);
  PodArray<Record> c;  // while b holds it, another array gets another block
  c.resize_uninitialized(kCount);
  EXPECT_NE(c.data(), first);
}

// Growing keeps the contents; a small array comes from malloc, a large one is never shorter than asked.
TEST(Memory, GrowingKeepsTheContents) {
  PodArray<std::uint32_t> a;
  for (std::uint32_t i = 0; i < 3'000'000; ++i) a.push_back(i);  // crosses the 2 MiB line several times
  ASSERT_EQ(a.size(), 3'000'000u);
  for (std::uint32_t i = 0; i < 3'000'000; i += 4099) ASSERT_EQ(a[i], i);
  PodArray<std::uint32_t> moved = std::move(a);
  EXPECT_EQ(moved.size(), 3'000'000u);
  EXPECT_EQ(moved[2'999'999], 2'999'999u);
  EXPECT_TRUE(a.empty());
}

}  // namespace
