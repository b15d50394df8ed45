#include "occupancy_grid/grid_io.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "occupancy_grid/grid_conversion.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;

fs::path outputDir(const std::string& name) {
  const fs::path dir = fs::path(STEREONAV_BINARY_DIR) / "test_output" / "occupancy_grid" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 23 x 17 grid at 0.05 m whose cells hold every G value 0..255 (and off-lattice limits).
DisparityTaggedGrid everyValueGrid() {
  GridLimits limits;
  limits.min_x = -0.4;
  limits.max_x = 0.75;
  limits.min_y = 1.2;
  limits.max_y = 2.05;
  limits.resolution = 0.05;
  DisparityTaggedGrid grid(limits, OccupancyScale{});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      grid.occupancyRow(row)[col] = static_cast<uint8_t>((col + row * grid.width()) % 256);
    }
  }
  return grid;
}

// MRPT cells hold P(free); ours p_occ = G / 255.
double mrptFreeProbability(uint8_t g) { return 1.0 - g / 255.0; }

// MRPT stores 8-bit log-odds: a probability p comes back as l2p(p2l(p)) (MRPT's own
// quantiser), which is within kQuantisation of p over the whole 0..1 range.
double mrptQuantised(double p) {
  using Grid = mrpt::maps::COccupancyGridMap2D;
  return Grid::l2p(Grid::p2l(static_cast<float>(p)));
}
constexpr double kQuantisation = 0.015;

TEST(GridIoTest, MrptConversionKeepsGeometryAndValuesWithinLogOddsQuantisation) {
  const DisparityTaggedGrid grid = everyValueGrid();
  ASSERT_EQ(grid.width(), 23);
  ASSERT_EQ(grid.height(), 17);
  const mrpt::maps::COccupancyGridMap2D mrpt_grid = toMrptOccupancyGrid(grid);
  ASSERT_EQ(static_cast<int>(mrpt_grid.getSizeX()), grid.width());
  ASSERT_EQ(static_cast<int>(mrpt_grid.getSizeY()), grid.height());
  EXPECT_NEAR(mrpt_grid.getXMin(), grid.minX(), 1e-6);
  EXPECT_NEAR(mrpt_grid.getYMin(), grid.minY(), 1e-6);
  EXPECT_NEAR(mrpt_grid.getResolution(), 0.05, 1e-7);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      // Same world point, same value: the cell centre maps to the same cell in both grids.
      const double x = grid.minX() + (col + 0.5) * grid.resolution();
      const double y = grid.minY() + (row + 0.5) * grid.resolution();
      const double expected = mrptFreeProbability(grid.occupancy(col, row));
      EXPECT_FLOAT_EQ(mrpt_grid.getPos(x, y), mrptQuantised(expected));
      EXPECT_NEAR(mrpt_grid.getPos(x, y), expected, kQuantisation)
          << "G=" << int(grid.occupancy(col, row));
    }
  }
}

TEST(GridIoTest, GridmapFileLoadsBackIntoMrpt) {
  const DisparityTaggedGrid grid = everyValueGrid();
  const fs::path path = outputDir("gridmap") / "map.gridmap.gz";
  saveMrptGridmap(grid, path.string());

  mrpt::maps::COccupancyGridMap2D loaded;
  mrpt::io::CFileGZInputStream file(path.string());
  mrpt::serialization::archiveFrom(file) >> loaded;
  ASSERT_EQ(static_cast<int>(loaded.getSizeX()), grid.width());
  ASSERT_EQ(static_cast<int>(loaded.getSizeY()), grid.height());
  EXPECT_NEAR(loaded.getXMin(), grid.minX(), 1e-6);
  EXPECT_NEAR(loaded.getYMax(), grid.maxY(), 1e-6);
  const OccupancyScale scale;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const uint8_t g = grid.occupancy(col, row);
      const double p_free = loaded.getCell(col, row);
      const double expected = mrptFreeProbability(g);
      const double quantisation = kQuantisation;
      EXPECT_FLOAT_EQ(p_free, mrptQuantised(expected)) << "G=" << int(g);
      EXPECT_NEAR(p_free, expected, quantisation) << "G=" << int(g);
      // Farther than the quantisation from the thresholds, the classes agree.
      const double free_p = mrptFreeProbability(static_cast<uint8_t>(scale.free_below));
      const double occupied_p = mrptFreeProbability(static_cast<uint8_t>(scale.occupied_above));
      if (std::abs(expected - free_p) > quantisation &&
          std::abs(expected - occupied_p) > quantisation) {
        const double g_back = (1.0 - p_free) * 255.0;
        const CellClass back = g_back < scale.free_below       ? CellClass::kFree
                               : g_back > scale.occupied_above ? CellClass::kOccupied
                                                               : CellClass::kUnknown;
        EXPECT_EQ(back, scale.classify(g)) << "G=" << int(g);
      }
    }
  }
}

TEST(GridIoTest, RosMapServerYamlLoadsBackWithTheSameCellClasses) {
  const DisparityTaggedGrid grid = everyValueGrid();
  const fs::path dir = outputDir("ros");
  saveRosMapServer(grid, (dir / "map.yaml").string());
  ASSERT_TRUE(fs::exists(dir / "map.pgm"));

  std::ifstream yaml_file(dir / "map.yaml");
  std::stringstream yaml;
  yaml << yaml_file.rdbuf();
  EXPECT_NE(yaml.str().find("image: map.pgm\n"), std::string::npos) << yaml.str();
  EXPECT_NE(yaml.str().find("negate: 0\n"), std::string::npos);

  mrpt::maps::COccupancyGridMap2D loaded;
  ASSERT_TRUE(loaded.loadFromROSMapServerYAML((dir / "map.yaml").string()));
  ASSERT_EQ(static_cast<int>(loaded.getSizeX()), grid.width());
  ASSERT_EQ(static_cast<int>(loaded.getSizeY()), grid.height());
  EXPECT_NEAR(loaded.getXMin(), grid.minX(), 1e-6);
  EXPECT_NEAR(loaded.getYMin(), grid.minY(), 1e-6);
  EXPECT_NEAR(loaded.getResolution(), grid.resolution(), 1e-7);
  const OccupancyScale scale;
  int counts[3] = {0, 0, 0};
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const uint8_t g = grid.occupancy(col, row);
      // Trinary map: MRPT sets occupied cells to 0, free ones to 1, the rest to 0.5.
      const float p_free = loaded.getCell(col, row);
      const CellClass loaded_class = p_free < 0.25f   ? CellClass::kOccupied
                                     : p_free > 0.75f ? CellClass::kFree
                                                      : CellClass::kUnknown;
      EXPECT_EQ(loaded_class, scale.classify(g)) << "G=" << int(g);
      ++counts[static_cast<int>(loaded_class)];
    }
  }
  // Every class is exercised, including the threshold values 49/50 and 150/151.
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(GridIoTest, ImageIsOnePixelPerCellWhiteFreeBlackOccupiedYUp) {
  DisparityTaggedGrid grid = everyValueGrid();
  grid.occupancyRow(0)[0] = 255;                   // bottom-left: occupied
  grid.occupancyRow(grid.height() - 1)[0] = 0;     // top-left: free
  const fs::path path = outputDir("png") / "map.png";
  saveGridImage(grid, path.string());
  const cv::Mat image = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC1);
  ASSERT_EQ(image.cols, grid.width());
  ASSERT_EQ(image.rows, grid.height());
  EXPECT_EQ(image.at<uint8_t>(grid.height() - 1, 0), 0);  // occupied is black, at the bottom
  EXPECT_EQ(image.at<uint8_t>(0, 0), 255);                // free is white, at the top
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      EXPECT_EQ(image.at<uint8_t>(grid.height() - 1 - row, col), 255 - grid.occupancy(col, row));
    }
  }
}

}  // namespace
}  // namespace stereonav
