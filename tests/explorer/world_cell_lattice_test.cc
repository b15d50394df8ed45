#include "explorer/world_cell_lattice.h"

#include <gtest/gtest.h>

#include <map>

namespace stereonav {
namespace {

TEST(WorldCellLatticeTest, CellsKeepTheirNamesAsTheGridGrowsByWholeCells) {
  WorldCellLattice lattice;
  GridFrame first;
  first.origin_x = -2.0;
  first.origin_y = 1.0;
  first.resolution = 0.05;
  lattice.anchor(first);
  GridFrame grown = first;
  grown.origin_x -= 0.05 * 40;
  lattice.anchor(grown);  // ignored: the first frame anchors
  // The cell holding (-1.975, 1.025) is the first grid's cell (0, 0), whatever the grid now is.
  EXPECT_EQ(lattice.cellAt(-1.975, 1.025), WorldCellLattice::Cell(0, 0));
  EXPECT_EQ(lattice.cellAt(-2.01, 0.99), WorldCellLattice::Cell(-1, -1));
  const cv::Point2d centre = lattice.centre({3, -2});
  EXPECT_NEAR(centre.x, -2.0 + 3.5 * 0.05, 1e-12);
  EXPECT_NEAR(centre.y, 1.0 - 1.5 * 0.05, 1e-12);
}

TEST(WorldCellMapTest, HoldsWhatWasSetInEveryDirectionThroughItsGrowth) {
  WorldCellMap<int> map;
  EXPECT_TRUE(map.empty());
  EXPECT_EQ(map.get({5, 5}), 0);
  EXPECT_TRUE(map.empty());  // reading sets nothing
  // Cells far apart on every side of the first one, each growing the map past the block it
  // adds, and some set twice; a std::map says what each must hold.
  std::map<WorldCellMap<int>::Cell, int> expected;
  const long spots[][2] = {{0, 0}, {1, 0}, {-300, 7}, {250, -400}, {-1000, -1000}, {64, 64},
                           {65, -65}, {1000, 999}, {0, 0}, {-300, 7}, {3, 2000}};
  int value = 1;
  for (const auto& spot : spots) {
    const WorldCellMap<int>::Cell cell(spot[0], spot[1]);
    map.at(cell) += value;
    expected[cell] += value;
    ++value;
    for (const auto& [set, held] : expected) ASSERT_EQ(map.get(set), held) << set.first << " " << set.second;
  }
  EXPECT_FALSE(map.empty());
  // Cells never set read as zero, beside the set ones and beyond the box.
  for (const long col : {-1001L, -999L, -1L, 2L, 66L, 1001L, 5000L}) {
    for (const long row : {-1001L, -1L, 1L, 63L, 2001L, -5000L}) {
      if (expected.count({col, row}) == 0) {
        EXPECT_EQ(map.get({col, row}), 0) << col << " " << row;
      }
    }
  }
  map.clear();
  EXPECT_TRUE(map.empty());
  EXPECT_EQ(map.get({0, 0}), 0);
}

}  // namespace
}  // namespace stereonav
