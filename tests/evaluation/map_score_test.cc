#include "evaluation/map_score.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "map_test_maps.h"

namespace stereonav {
namespace {

// A wall across the middle row of a 5 x 5 room of 1 m cells.
RosMap wallAcrossTheMiddle() {
  return drawnMap({".....",
                   ".....",
                   "#####",
                   ".....",
                   "....."});
}

// Two occupied cells on the wall, one beside it, one two rows away; a gap in the wall mapped free.
RosMap mapOfTheWall() {
  return drawnMap({"..???",
                   "#????",
                   "##.#?",
                   "?????",
                   "...?#"});
}

TEST(MapScore, PrecisionAndRecallAcceptOccupiedCellsWithinTheTolerance) {
  MapScoreOptions options;
  options.tolerance_cells = 1;
  const MapScore score = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), options);
  // Occupied: (0,3) beside the wall, (0,2) (1,2) (3,2) on it, (4,0) two rows off.
  EXPECT_EQ(score.map_occupied, 5u);
  EXPECT_EQ(score.map_occupied_correct, 4u);
  EXPECT_DOUBLE_EQ(score.precision(), 0.8);
  // Every wall cell has a mapped obstacle within one cell, x = 2 and x = 4 through their neighbours.
  EXPECT_EQ(score.truth_obstacles, 5u);
  EXPECT_DOUBLE_EQ(score.recall(), 1.0);
}

TEST(MapScore, ZeroToleranceCountsOnlyExactCells) {
  MapScoreOptions options;
  options.tolerance_cells = 0;
  const MapScore score = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), options);
  EXPECT_DOUBLE_EQ(score.precision(), 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(score.recall(), 3.0 / 5.0);  // x = 0, 1, 3
}

TEST(MapScore, FalseFreeIsTheShareOfObstacleCellsMappedFree) {
  const MapScore score = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), {});
  EXPECT_EQ(score.truth_obstacles_free, 1u);  // the gap at x = 2
  EXPECT_DOUBLE_EQ(score.falseFree(), 0.2);
}

TEST(MapScore, CoverageIsOverTheFreeSpaceReachableFromTheStart) {
  MapScoreOptions options;
  options.start = std::make_pair(1.5, 0.5);  // below the wall: rows 0 and 1, 10 cells
  const MapScore from_start = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), options);
  EXPECT_TRUE(from_start.coverage_from_start);
  EXPECT_EQ(from_start.reachable_free, 10u);
  EXPECT_DOUBLE_EQ(from_start.coverage(), 0.3);

  // Without a start: all 20 free cells, 3 mapped free below the wall and 2 above it.
  const MapScore everywhere = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), {});
  EXPECT_FALSE(everywhere.coverage_from_start);
  EXPECT_EQ(everywhere.reachable_free, 20u);
  EXPECT_DOUBLE_EQ(everywhere.coverage(), 0.25);
}

TEST(MapScore, AStartOnAnObstacleIsRejected) {
  MapScoreOptions options;
  options.start = std::make_pair(2.5, 2.5);
  EXPECT_THROW(scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), options), std::invalid_argument);
}

TEST(MapScore, MapsWithOtherOriginAndResolutionAreAlignedByWorldCoordinates) {
  const RosMap truth = drawnMap({"#######",
                                 "#..#..#",
                                 "#.....#",
                                 "#######"},
                                1.0, 10.0, 20.0);
  // The truth drawn again at 0.25 m cells from another origin, reaching past it on every side.
  cv::Mat1b classes(24, 40);
  const double x0 = 8.5, y0 = 18.75, r = 0.25;
  for (int iy = 0; iy < classes.rows; ++iy) {
    for (int ix = 0; ix < classes.cols; ++ix) {
      classes(iy, ix) = static_cast<uint8_t>(truth.at(x0 + (ix + 0.5) * r, y0 + (iy + 0.5) * r));
    }
  }
  MapScoreOptions options;
  options.tolerance_cells = 0;
  options.start = std::make_pair(11.5, 21.5);
  const MapScore score = scoreMap(RosMap(r, x0, y0, classes), truth, options);
  EXPECT_EQ(score.map_occupied, 19u);
  EXPECT_DOUBLE_EQ(score.precision(), 1.0);
  EXPECT_DOUBLE_EQ(score.recall(), 1.0);
  EXPECT_DOUBLE_EQ(score.falseFree(), 0.0);
  EXPECT_EQ(score.reachable_free, 9u);
  EXPECT_DOUBLE_EQ(score.coverage(), 1.0);

  // Shifted by one truth cell, the same picture is wrong almost everywhere.
  const MapScore shifted = scoreMap(RosMap(r, x0 + 1.0, y0, classes), truth, options);
  EXPECT_GT(shifted.falseFree(), 0.1);
  EXPECT_LT(shifted.coverage(), 0.7);
}

TEST(MapScore, CellsOutsideTheTruthsBoundsAreNotScored) {
  const RosMap truth = drawnMap({"??????",
                                 "?#..#?",
                                 "??????"});
  const RosMap map = drawnMap({"######",
                               "##..##",
                               "######"});
  const MapScore score = scoreMap(map, truth, {});
  EXPECT_EQ(score.map_occupied, 2u);
  EXPECT_DOUBLE_EQ(score.precision(), 1.0);
  EXPECT_DOUBLE_EQ(score.coverage(), 1.0);
}

TEST(MapScore, WithPosesOnlyObstaclesInViewCountForRecall) {
  // Walls at both ends of a room; a robot in the middle looks east at the east wall only.
  const RosMap truth = drawnMap({"#.......#",
                                 "#.......#",
                                 "#.......#",
                                 "#.......#",
                                 "#.......#"});
  const RosMap map = drawnMap({"????????#",
                               "????????#",
                               "????????#",
                               "????????#",
                               "????????#"});
  EXPECT_DOUBLE_EQ(scoreMap(map, truth, {}).recall(), 0.5);

  MapScoreOptions options;
  options.poses = {mrpt::poses::CPose2D(4.5, 2.5, 0.0)};
  options.view_fov_deg = 90.0;
  options.view_range_m = 10.0;
  const MapScore score = scoreMap(map, truth, options);
  EXPECT_TRUE(score.obstacles_in_view_only);
  EXPECT_EQ(score.truth_obstacles, 5u);
  EXPECT_DOUBLE_EQ(score.recall(), 1.0);
  // Coverage starts from the first pose: the whole room is reachable, none of it mapped free.
  EXPECT_EQ(score.reachable_free, 35u);
  EXPECT_DOUBLE_EQ(score.coverage(), 0.0);
}

TEST(MapScore, TextAndJsonCarryTheSameNumbers) {
  const MapScore score = scoreMap(mapOfTheWall(), wallAcrossTheMiddle(), {});
  EXPECT_NE(score.toText().find("occupied precision 0.8000"), std::string::npos);
  EXPECT_NE(score.toText().find("within 1 cell(s)"), std::string::npos);
  EXPECT_NE(score.toJson().find("\"precision\": 0.8,"), std::string::npos);
  EXPECT_NE(score.toJson().find("\"false_free\": 0.2,"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
