#include "explorer/seen_free_memory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_grids.h"

namespace stereonav {
namespace {

bool remembers(const SeenFreeMemory& memory, double x, double y) {
  const std::vector<cv::Point2d> cells = memory.cells();
  return std::any_of(cells.begin(), cells.end(),
                     [&](const cv::Point2d& centre) { return std::hypot(centre.x - x, centre.y - y) < 1e-6; });
}

// A 6 m x 4 m room, all known free, with a wall across x = 2.5 from y = 2 up.
TestGrid roomWithAWall() {
  TestGrid cells(60, 40);
  cells.occupied(0, 0, 59, 39).free(1, 1, 58, 38).occupied(25, 20, 25, 38);
  return cells;
}

TEST(SeenFreeMemoryTest, RemembersFreeCellsInViewWithinRangeAndNotBehindAWall) {
  const TestGrid cells = roomWithAWall();
  SeenFreeMemoryOptions options;  // 2 m, 90 degrees
  SeenFreeMemory memory(options);
  memory.update(cells.grid(), mrpt::poses::CPose2D(1.03, 1.96, 0.0));  // facing east
  // Ahead within 2 m: cell centre (2.95, 1.55) is 1.96 m away, 12 degrees off the heading.
  EXPECT_TRUE(remembers(memory, 2.95, 1.55));
  EXPECT_TRUE(remembers(memory, 1.55, 1.95));
  // Ahead but beyond 2 m: (3.15, 1.95) is 2.12 m away.
  EXPECT_FALSE(remembers(memory, 3.15, 1.95));
  // Within range, out of the 90 degree view: behind, and 60 degrees to the left.
  EXPECT_FALSE(remembers(memory, 0.55, 1.95));
  EXPECT_FALSE(remembers(memory, 1.55, 2.85));
  // Within range and view, but behind the wall: (2.75, 2.55) is 1.82 m away, 19 degrees left.
  EXPECT_FALSE(remembers(memory, 2.75, 2.55));
  // The wall itself is not free, and the cells beside it are part wall, part floor.
  EXPECT_FALSE(remembers(memory, 2.55, 2.25));
  EXPECT_FALSE(remembers(memory, 2.45, 2.05));
  EXPECT_FALSE(remembers(memory, 2.45, 1.95));
  EXPECT_TRUE(remembers(memory, 2.45, 1.85));
  // Everything remembered is a free cell of the map, in view, within range.
  for (const cv::Point2d& centre : memory.cells()) {
    const double dx = centre.x - 1.03, dy = centre.y - 1.96;
    EXPECT_LE(std::hypot(dx, dy), 2.0);
    EXPECT_LE(std::abs(std::atan2(dy, dx)), M_PI / 4 + 1e-9);
    int col = 0, row = 0;
    ASSERT_TRUE(cells.grid().cellAt(centre.x, centre.y, col, row));
    EXPECT_EQ(cells.grid().occupancy(col, row), TestGrid::kFreeG);
  }
}

TEST(SeenFreeMemoryTest, KeepsWhatItSawWhenTheMapSmearsItAndTheGridGrows) {
  TestGrid cells = roomWithAWall();
  SeenFreeMemory memory(SeenFreeMemoryOptions{});
  memory.update(cells.grid(), mrpt::poses::CPose2D(1.03, 1.96, 0.0));
  const size_t seen = memory.size();
  ASSERT_GT(seen, 100u);
  // A far reading smears the floor ahead: the next view from here sees it unknown, and the
  // memory neither forgets it nor adds to it.
  cells.unknown(20, 15, 24, 24);
  memory.update(cells.grid(), mrpt::poses::CPose2D(1.03, 1.96, 0.0));
  EXPECT_EQ(memory.size(), seen);
  EXPECT_TRUE(remembers(memory, 2.05, 1.95));
  // The grid grows by whole cells to the west and south: the same world cells are remembered.
  DisparityTaggedGrid grown = cells.grid();
  grown.growToInclude(WorldBounds{-1.0, 2.0, -1.0, 2.0}, 0.0);
  ASSERT_LT(grown.minX(), 0.0);
  memory.update(grown, mrpt::poses::CPose2D(1.03, 1.96, 0.0));
  EXPECT_EQ(memory.size(), seen);
  EXPECT_TRUE(remembers(memory, 2.95, 1.55));
}

TEST(SeenFreeMemoryTest, TheFloorUnderTheBodyDoesNotHideWhatIsAhead) {
  // The cameras never see the floor under the robot: at the start it is unknown.
  TestGrid cells = roomWithAWall();
  cells.unknown(8, 17, 12, 21);
  SeenFreeMemory memory(SeenFreeMemoryOptions{});
  memory.update(cells.grid(), mrpt::poses::CPose2D(1.03, 1.96, 0.0));
  EXPECT_TRUE(remembers(memory, 2.05, 1.95));
  EXPECT_FALSE(remembers(memory, 1.15, 1.95));  // unknown: not seen free
}

}  // namespace
}  // namespace stereonav
