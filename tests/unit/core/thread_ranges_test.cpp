// ThreadRanges (core/thread_ranges.hpp): rows split into contiguous ranges of about equal cost.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "sloshsph/core/thread_ranges.hpp"

namespace sloshsph {
namespace {

// The rows of the PPE of a tank in miniature: 700 fluid rows of cost 25, then 300 wall rows of 8.
double ppe_like_cost(std::size_t i) { return i < 700 ? 25.0 : 8.0; }

double range_cost(const ThreadRanges& r, int part, double (*cost)(std::size_t)) {
  double sum = 0.0;
  for (std::size_t i = r.begin(part); i < r.end(part); ++i) sum += cost(i);
  return sum;
}

TEST(ThreadRanges, RangesCoverTheRowsInOrder) {
  for (int parts : {1, 2, 3, 8}) {
    ThreadRanges r;
    r.balance(1000, parts, ppe_like_cost);
    ASSERT_EQ(r.parts(), parts);
    EXPECT_EQ(r.begin(0), 0u);
    EXPECT_EQ(r.end(parts - 1), 1000u);
    for (int k = 0; k + 1 < parts; ++k) EXPECT_EQ(r.end(k), r.begin(k + 1));
    for (int k = 0; k < parts; ++k) EXPECT_LE(r.begin(k), r.end(k));
  }
}

TEST(ThreadRanges, EachRangeWithinOneRowOfAnEqualShare) {
  // Total 700 * 25 + 300 * 8 = 19,900; an equal split by rows (schedule(static)) would give
  // the first of two threads 12,500 and the second 7,400.
  for (int parts : {2, 3, 4}) {
    ThreadRanges r;
    r.balance(1000, parts, ppe_like_cost);
    const double share = 19900.0 / parts;
    for (int k = 0; k < parts; ++k) EXPECT_NEAR(range_cost(r, k, ppe_like_cost), share, 25.0) << parts << " parts";
  }
}

TEST(ThreadRanges, EvenSplitIsTheStaticSchedule) {
  ThreadRanges r;
  r.even(10, 2);
  EXPECT_EQ(r.end(0), 5u);
  r.even(0, 2);
  EXPECT_EQ(r.rows(), 0u);
  EXPECT_EQ(r.end(0), 0u);
}

TEST(ThreadRanges, BlocksFollowTheRowBounds) {
  ThreadRanges rows;
  rows.balance(1000, 2, ppe_like_cost);  // the bound near row 398
  ThreadRanges blocks;
  blocks.blocks_of(rows, 256);
  ASSERT_EQ(blocks.parts(), 2);
  EXPECT_EQ(blocks.rows(), 4u);  // 1000 rows are 4 blocks of 256
  EXPECT_EQ(blocks.end(0), (rows.end(0) + 128) / 256);
  EXPECT_EQ(blocks.end(1), 4u);
}

TEST(ThreadRanges, ParallelLoopVisitsEveryRowOnce) {
  for (int threads : {1, 2, 3}) {
    ThreadRanges r;
    r.balance(1000, threads, ppe_like_cost);
    std::vector<int> visits(1000, 0);
    parallel_for_ranges(r, [&](std::size_t i) { ++visits[i]; });  // each row is one thread's
    EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), 1000) << threads << " ranges";
  }
  // A region with fewer threads than ranges works them round-robin: inside an active parallel
  // region, with nesting off, the inner region has one thread for four ranges.
  ThreadRanges r;
  r.balance(1000, 4, ppe_like_cost);
  std::vector<int> visits(1000, 0);
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(1);
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    parallel_for_ranges(r, [&](std::size_t i) { ++visits[i]; });
  }
  omp_set_max_active_levels(levels);
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), 1000);
}

TEST(ThreadRanges, ZeroCostsSplitEvenly) {
  ThreadRanges r;
  r.balance(10, 2, [](std::size_t) { return 0.0; });
  EXPECT_EQ(r.end(0), 5u);
  EXPECT_EQ(r.end(1), 10u);
}

}  // namespace
}  // namespace sloshsph
