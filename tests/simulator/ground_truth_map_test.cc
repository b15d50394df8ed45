#include "simulator/ground_truth_map.h"

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>

#include "world_text.h"

namespace stereonav {
namespace {

GroundTruthMapOptions tenCentimetres(double margin) {
  GroundTruthMapOptions options;
  options.resolution_m = 0.1;
  options.margin_m = margin;
  return options;
}

TEST(GroundTruthMap, BoxOccupiesExactlyTheCellsItCovers) {
  // x 0.8..1.2, y 0.9..1.1: cells ix 8..11, iy 9..10.
  const World world = worldFromText("[world]\nbounds = 0 0 2 2\n[box.b]\ncenter = 1 1\nsize = 0.4 0.2\n");
  const GroundTruthMap map(world, tenCentimetres(0.0));
  ASSERT_EQ(map.width(), 20);
  ASSERT_EQ(map.height(), 20);
  for (int iy = 0; iy < 20; ++iy) {
    for (int ix = 0; ix < 20; ++ix) {
      const bool inside = ix >= 8 && ix <= 11 && iy >= 9 && iy <= 10;
      EXPECT_EQ(map.cell(ix, iy), inside ? GroundTruthMap::kOccupied : GroundTruthMap::kFree) << ix << "," << iy;
    }
  }
}

TEST(GroundTruthMap, TurnedBoxAndCylinder) {
  // A 0.2 x 0.2 box turned 45 degrees at (0.5, 0.5) reaches 0.1414 from its centre along the
  // axes: it overlaps the four cells meeting at its centre and their four axis neighbours.
  const World world = worldFromText(
      "[world]\nbounds = 0 0 2 2\n[box.b]\ncenter = 0.5 0.5\nsize = 0.2 0.2\nyaw_deg = 45\n"
      "[cylinder.c]\ncenter = 1.5 1.5\nradius = 0.05\n");
  const GroundTruthMap map(world, tenCentimetres(0.0));
  int occupied = 0;
  for (int iy = 0; iy < 20; ++iy) {
    for (int ix = 0; ix < 20; ++ix) occupied += map.cell(ix, iy) == GroundTruthMap::kOccupied;
  }
  for (int ix : {4, 5}) {
    for (int iy : {3, 4, 5, 6}) EXPECT_EQ(map.cell(ix, iy), GroundTruthMap::kOccupied);
  }
  for (int iy : {4, 5}) {
    for (int ix : {3, 6}) EXPECT_EQ(map.cell(ix, iy), GroundTruthMap::kOccupied);
  }
  EXPECT_EQ(map.cell(3, 3), GroundTruthMap::kFree);
  // The cylinder's centre is a cell corner: the four cells around it.
  for (int ix : {14, 15}) {
    for (int iy : {14, 15}) EXPECT_EQ(map.cell(ix, iy), GroundTruthMap::kOccupied);
  }
  EXPECT_EQ(occupied, 12 + 4);
}

TEST(GroundTruthMap, OnlyObstaclesInTheBodyHeightBandCount) {
  const World world = worldFromText("[world]\nbounds = 0 0 2 2\n[table.t]\ncenter = 1 1\nsize = 1.2 0.8\n");
  GroundTruthMapOptions tall = tenCentimetres(0.0);
  tall.band_max_z = 1.0;
  GroundTruthMapOptions low = tall;
  low.band_max_z = 0.5;
  const GroundTruthMap with_top(world, tall);
  const GroundTruthMap legs_only(world, low);
  EXPECT_EQ(with_top.cell(10, 10), GroundTruthMap::kOccupied);  // under the middle of the top
  EXPECT_EQ(legs_only.cell(10, 10), GroundTruthMap::kFree);
  // A leg stands at (1 - 0.53, 1 - 0.33) = (0.47, 0.67): cell (4, 6).
  EXPECT_EQ(legs_only.cell(4, 6), GroundTruthMap::kOccupied);
}

TEST(GroundTruthMap, WrittenMapLoadsInMrptWithTheSameCells) {
  const World world = worldFromText("[world]\nbounds = 0 0 2 2\n[box.b]\ncenter = 1 1\nsize = 0.4 0.2\n");
  const GroundTruthMap map(world, tenCentimetres(0.5));
  EXPECT_EQ(map.width(), 30);
  EXPECT_DOUBLE_EQ(map.xMin(), -0.5);
  EXPECT_DOUBLE_EQ(map.yMin(), -0.5);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.1);
  EXPECT_EQ(map.cell(0, 0), GroundTruthMap::kUnknown);
  const std::filesystem::path directory =
      std::filesystem::path(STEREONAV_BINARY_DIR) / "simulator_test_output";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string yaml = (directory / "truth.yaml").string();
  map.writeRosMap(yaml);
  // Only the two outputs, no temporaries left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), std::filesystem::directory_iterator()), 2);

  const cv::Mat image = cv::imread((directory / "truth.pgm").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC1);
  // Image row 0 is the top of the map: box cell (ix 13, iy 14 with the 5-cell margin) is at
  // row 30 - 1 - 14 = 15.
  EXPECT_EQ(image.at<uint8_t>(15, 13), GroundTruthMap::kOccupied);
  EXPECT_EQ(image.at<uint8_t>(14, 13), GroundTruthMap::kOccupied);
  EXPECT_EQ(image.at<uint8_t>(13, 13), GroundTruthMap::kFree);

  mrpt::maps::COccupancyGridMap2D grid;
  ASSERT_TRUE(grid.loadFromROSMapServerYAML(yaml));
  EXPECT_NEAR(grid.getResolution(), 0.1, 1e-6);
  EXPECT_NEAR(grid.getXMin(), -0.5, 1e-6);
  EXPECT_NEAR(grid.getYMin(), -0.5, 1e-6);
  // MRPT cells hold the probability of being free.
  EXPECT_LT(grid.getPos(1.0, 1.0), 1.0 - 0.65);
  EXPECT_LT(grid.getPos(1.15, 1.05), 1.0 - 0.65);
  EXPECT_GT(grid.getPos(0.3, 0.3), 1.0 - 0.196);
  EXPECT_GT(grid.getPos(1.25, 1.0), 1.0 - 0.196);
}

}  // namespace
}  // namespace stereonav
