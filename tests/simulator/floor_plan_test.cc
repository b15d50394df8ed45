#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "common/ini_section.h"
#include "simulator/ground_truth_map.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

// A hand-drawn 10 x 8 floor plan at 0.5 m, its lower-left corner at (-1, -2): a ring of wall
// round the border and an interior wall in column 4, image rows 1..4 (world rows 3..6 from the
// bottom: image row 0 is the top, the largest y, as in every map_server image).
constexpr int kWidth = 10, kHeight = 8;
constexpr double kResolution = 0.5, kOriginX = -1.0, kOriginY = -2.0;

bool drawnOccupied(int col, int image_row) {
  const bool ring = image_row == 0 || image_row == kHeight - 1 || col == 0 || col == kWidth - 1;
  const bool interior = col == 4 && image_row >= 1 && image_row <= 4;
  return ring || interior;
}

class FloorPlanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest runs the tests of this fixture in parallel processes.
    directory_ = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/floor_plan/" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_ + "/plans");
    cv::Mat1b image(kHeight, kWidth, uchar{254});
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        if (drawnOccupied(col, row)) image(row, col) = 0;
      }
    }
    ASSERT_TRUE(cv::imwrite(directory_ + "/plans/flat.pgm", image));
    std::ofstream(directory_ + "/plans/flat.yaml")
        << "image: flat.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\n"
        << "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  }

  // Writes `sections` as a world file beside plans/ and loads it.
  World load(const std::string& sections) {
    const std::string path = directory_ + "/world.ini";
    std::ofstream(path) << "[texture.paint]\ntype = paint\n" << sections;
    return loadWorld(path);
  }

  std::string directory_;
};

TEST_F(FloorPlanTest, OccupiedCellsBecomeWallsWhereTheImageSaysAndStraightWallsAreOneBox) {
  const World world = load("[floor_plan.house]\nmap = plans/flat.yaml\nheight = 2.4\n");
  // The ring's top and bottom rows, its two sides between them, the interior wall.
  ASSERT_EQ(world.solids.size(), 5u);
  for (const Solid& solid : world.solids) {
    EXPECT_EQ(solid.shape, Solid::Shape::kBox);
    EXPECT_DOUBLE_EQ(solid.z_min, 0.0);
    EXPECT_DOUBLE_EQ(solid.z_max, 2.4);
  }
  for (int image_row = 0; image_row < kHeight; ++image_row) {
    for (int col = 0; col < kWidth; ++col) {
      const double x = kOriginX + (col + 0.5) * kResolution;
      const double y = kOriginY + (kHeight - 1 - image_row + 0.5) * kResolution;
      bool inside = false;
      for (const Solid& solid : world.solids) {
        const FloorExtent extent = solid.floorExtent();
        inside = inside || (x > extent.x_min && x < extent.x_max && y > extent.y_min && y < extent.y_max);
      }
      EXPECT_EQ(inside, drawnOccupied(col, image_row)) << "cell " << col << ", image row " << image_row;
    }
  }
  // Nothing outside the drawn cells: the walls fill the plan's extent exactly.
  double x_min = 1e9, y_min = 1e9, x_max = -1e9, y_max = -1e9;
  for (const Solid& solid : world.solids) {
    const FloorExtent extent = solid.floorExtent();
    x_min = std::min(x_min, extent.x_min), y_min = std::min(y_min, extent.y_min);
    x_max = std::max(x_max, extent.x_max), y_max = std::max(y_max, extent.y_max);
  }
  EXPECT_NEAR(x_min, kOriginX, 1e-9);
  EXPECT_NEAR(y_min, kOriginY, 1e-9);
  EXPECT_NEAR(x_max, kOriginX + kWidth * kResolution, 1e-9);
  EXPECT_NEAR(y_max, kOriginY + kHeight * kResolution, 1e-9);
}

TEST_F(FloorPlanTest, FlatShareGivesThatShareOfWallsTheFlatTextureFromItsSeed) {
  const auto textures = [&](const std::string& extra) {
    std::multiset<int> used;
    for (const Solid& solid : load("[floor_plan.house]\nmap = plans/flat.yaml\n" + extra).solids) {
      used.insert(solid.texture);
    }
    return used;
  };
  const World all_flat = load("[floor_plan.house]\nmap = plans/flat.yaml\nflat_share = 1\nflat_texture = paint\n");
  const int paint = all_flat.solids.front().texture;
  EXPECT_EQ(all_flat.textures[paint].kind, SurfaceTexture::Kind::kPaint);
  for (const Solid& solid : all_flat.solids) EXPECT_EQ(solid.texture, paint);
  EXPECT_EQ(textures("").count(paint), 0u);
  const std::string half = "flat_share = 0.5\nflat_texture = paint\nseed = 3\n";
  EXPECT_EQ(textures(half), textures(half));  // deterministic
}

TEST_F(FloorPlanTest, TheGroundTruthMapHoldsThePlansWalls) {
  const World world = load("[floor_plan.house]\nmap = plans/flat.yaml\n");
  const GroundTruthMap truth(world, GroundTruthMapOptions{});
  const auto at = [&](double x, double y) {
    return truth.cell(static_cast<int>((x - truth.xMin()) / truth.resolution()),
                      static_cast<int>((y - truth.yMin()) / truth.resolution()));
  };
  // The interior wall's middle is occupied, the room beside it free.
  EXPECT_EQ(at(kOriginX + 4.5 * kResolution, kOriginY + 5.25 * kResolution), GroundTruthMap::kOccupied);
  EXPECT_EQ(at(kOriginX + 4.5 * kResolution, kOriginY + 1.75 * kResolution), GroundTruthMap::kFree);
  EXPECT_EQ(at(kOriginX + 2.5 * kResolution, kOriginY + 5.25 * kResolution), GroundTruthMap::kFree);
}

TEST_F(FloorPlanTest, ErrorsNameTheSectionKeyAndFile) {
  const auto error = [&](const std::string& sections) -> std::string {
    try {
      load(sections);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  const std::string missing = error("[floor_plan.house]\nmap = plans/none.yaml\n");
  EXPECT_NE(missing.find("[floor_plan.house] map"), std::string::npos) << missing;
  EXPECT_NE(missing.find("none.yaml"), std::string::npos) << missing;
  const std::string no_flat = error("[floor_plan.house]\nmap = plans/flat.yaml\nflat_share = 0.3\n");
  EXPECT_NE(no_flat.find("[floor_plan.house] flat_texture"), std::string::npos) << no_flat;
  // The plan reaches x = 4 m: beyond a 2 m world limit, said once for the section and key.
  const std::string far = error("[world]\nmax_extent_m = 2\n[floor_plan.house]\nmap = plans/flat.yaml\n");
  EXPECT_NE(far.find("[floor_plan.house] map: 4 is beyond [world] max_extent_m"), std::string::npos) << far;
  EXPECT_EQ(far.find("[floor_plan.house]"), far.rfind("[floor_plan.house]")) << far;
  const std::string share = error("[floor_plan.house]\nmap = plans/flat.yaml\nflat_share = 1.5\n");
  EXPECT_NE(share.find("flat_share"), std::string::npos) << share;
}

}  // namespace
}  // namespace stereonav
