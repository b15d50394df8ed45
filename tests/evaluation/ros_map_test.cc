#include "occupancy_grid/ros_map.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "simulator/ground_truth_map.h"
#include "simulator/world_loader.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

class RosMapTest : public ::testing::Test {
 protected:

  std::string writeYaml(const std::string& text) {
    const std::string path = scratch_.file("map.yaml");
    std::ofstream(path) << text;
    return path;
  }

  // A 3 x 2 image, top row first: black, mid grey 128, white; grey 60, 205, 230.
  void writeImage() {
    cv::Mat1b image = (cv::Mat1b(2, 3) << 0, 128, 255, 60, 205, 230);
    cv::imwrite(scratch_.file("map.pgm"), image);
  }

  test_support::ScratchDirectory scratch_;
};

TEST_F(RosMapTest, ClassifiesPixelsByTheYamlsThresholdsWithTheImageTopAtMaxY) {
  writeImage();
  const RosMap map = loadRosMap(writeYaml(
      "image: map.pgm\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\n"
      "occupied_thresh: 0.65\nfree_thresh: 0.196  # map_server's usual values\n"));
  EXPECT_DOUBLE_EQ(map.resolution(), 0.5);
  EXPECT_DOUBLE_EQ(map.xMin(), -1.0);
  EXPECT_DOUBLE_EQ(map.yMin(), 2.0);
  ASSERT_EQ(map.width(), 3);
  ASSERT_EQ(map.height(), 2);
  // Occupancy (255 - grey) / 255: 1.0, 0.498, 0 on the top row (iy 1); 0.765, 0.196, 0.098 below.
  EXPECT_EQ(map.cell(0, 1), CellClass::kOccupied);
  EXPECT_EQ(map.cell(1, 1), CellClass::kUnknown);
  EXPECT_EQ(map.cell(2, 1), CellClass::kFree);
  EXPECT_EQ(map.cell(0, 0), CellClass::kOccupied);
  EXPECT_EQ(map.cell(1, 0), CellClass::kUnknown);  // 50/255 = 0.1961 is not below 0.196
  EXPECT_EQ(map.cell(2, 0), CellClass::kFree);
  // World lookup: x -1..0.5, y 2..3.
  EXPECT_EQ(map.at(-0.9, 2.9), CellClass::kOccupied);
  EXPECT_EQ(map.at(0.4, 2.1), CellClass::kFree);
  EXPECT_EQ(map.at(0.6, 2.1), CellClass::kUnknown);
  EXPECT_EQ(map.at(-0.9, 1.9), CellClass::kUnknown);
}

TEST_F(RosMapTest, NegateSwapsBlackAndWhiteButNotTheThresholds) {
  writeImage();
  const RosMap map = loadRosMap(writeYaml(
      "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.9\nfree_thresh: 0.3\n"));
  EXPECT_EQ(map.cell(0, 1), CellClass::kFree);      // 0 / 255
  EXPECT_EQ(map.cell(2, 1), CellClass::kOccupied);  // 255 / 255
  EXPECT_EQ(map.cell(0, 0), CellClass::kFree);      // 60 / 255 = 0.235
  EXPECT_EQ(map.cell(2, 0), CellClass::kOccupied);  // 230 / 255 = 0.902
  EXPECT_EQ(map.cell(1, 0), CellClass::kUnknown);   // 205 / 255 = 0.80
}

TEST_F(RosMapTest, BadInputNamesTheFileAndTheKey) {
  writeImage();
  auto message = [&](const std::string& yaml) {
    try {
      loadRosMap(writeYaml(yaml));
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("image: map.pgm\norigin: [0, 0, 0]\n").find("missing key 'resolution'"), std::string::npos);
  EXPECT_NE(message("image: map.pgm\nresolution: fine\norigin: [0, 0, 0]\n").find("resolution: expected a number in"),
            std::string::npos);
  EXPECT_NE(message("image: map.pgm\nresolution: 1\norigin: [0, 0, 0.5]\n").find("rotated"), std::string::npos);
  EXPECT_NE(message("image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: raw\n").find("mode"),
            std::string::npos);
  EXPECT_NE(message("image: nothere.pgm\nresolution: 1\norigin: [0, 0, 0]\n").find("nothere.pgm"),
            std::string::npos);
  EXPECT_NE(message("image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n").find("no error"), std::string::npos);
  EXPECT_THROW(loadRosMap(scratch_.file("absent.yaml")), std::runtime_error);
}

TEST_F(RosMapTest, ReadsTheSimulatorsGroundTruthMapCellForCell) {
  const World world = loadWorld(std::string(STEREONAV_SOURCE_DIR) + "/ini/worlds/table_room.ini");
  const GroundTruthMap truth(world, GroundTruthMapOptions{});
  const std::string yaml = scratch_.file("truth.yaml");
  truth.writeRosMap(yaml);
  const RosMap map = loadRosMap(yaml);
  ASSERT_EQ(map.width(), truth.width());
  ASSERT_EQ(map.height(), truth.height());
  EXPECT_NEAR(map.xMin(), truth.xMin(), 1e-9);
  EXPECT_NEAR(map.yMin(), truth.yMin(), 1e-9);
  int occupied = 0;
  for (int iy = 0; iy < truth.height(); ++iy) {
    for (int ix = 0; ix < truth.width(); ++ix) {
      const CellClass expected = truth.cell(ix, iy) == GroundTruthMap::kOccupied ? CellClass::kOccupied
                                 : truth.cell(ix, iy) == GroundTruthMap::kFree   ? CellClass::kFree
                                                                                  : CellClass::kUnknown;
      ASSERT_EQ(map.cell(ix, iy), expected) << ix << "," << iy;
      occupied += expected == CellClass::kOccupied;
    }
  }
  EXPECT_GT(occupied, 100);
}

}  // namespace
}  // namespace stereonav
