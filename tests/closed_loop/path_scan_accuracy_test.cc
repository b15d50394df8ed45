// The stereo scans along a path against the renderer's truth (closed_loop/path_scan_accuracy.h),
// in a corridor whose end wall is textured or flat-painted.
#include "closed_loop/path_scan_accuracy.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "corridor_world.h"
#include "shipped_config.h"

namespace stereonav {
namespace {

// The corridor of corridor_world.h, its end wall textured or painted.
World corridorEndingIn(const std::string& end_texture) { return testing::corridorWorld(0.8, end_texture); }

// Five frames down the corridor's middle, looking at the end wall from 3.45 m to 3.05 m.
std::vector<mrpt::poses::CPose2D> downTheCorridor() {
  std::vector<mrpt::poses::CPose2D> poses;
  for (int i = 0; i < 5; ++i) poses.emplace_back(1.5 + 0.1 * i, 0.8, 0.0);
  return poses;
}

TEST(PathScanAccuracyTest, TexturedWallsAreReadWhereTheyStand) {
  const ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  const ScanAccuracy accuracy =
      scanAccuracyAlongPath(config, corridorEndingIn("rough"), downTheCorridor(), 2, ScanAccuracyOptions{});
  // Frames 0, 2 and 4 of the five.
  EXPECT_EQ(accuracy.frames, 3u);
  EXPECT_EQ(accuracy.columns, 3u * static_cast<size_t>(config.simulator.rig.reference.width));
  // Every column sees a wall; most of them are read, within a pixel of the truth, and hardly any
  // nearer than the wall.
  EXPECT_GT(accuracy.read, accuracy.columns * 8 / 10);
  EXPECT_GT(accuracy.agreeing, accuracy.read * 9 / 10);
  EXPECT_LT(accuracy.phantoms, accuracy.read / 50 + 1);
}

TEST(PathScanAccuracyTest, AFlatPaintedWallWithinReachIsMissed) {
  const ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  // From 1.45 m to 1.05 m before the painted end wall: in the middle of the image it is the
  // nearest obstacle, within reach, and stereo has nothing to match on it.
  std::vector<mrpt::poses::CPose2D> poses;
  for (int i = 0; i < 5; ++i) poses.emplace_back(3.5 + 0.1 * i, 0.8, 0.0);
  const ScanAccuracy flat = scanAccuracyAlongPath(config, corridorEndingIn("flat"), poses, 1, ScanAccuracyOptions{});
  const ScanAccuracy rough = scanAccuracyAlongPath(config, corridorEndingIn("rough"), poses, 1, ScanAccuracyOptions{});
  // Every column sees a wall within reach: the end wall in the middle (it fills the columns within
  // atan(0.8 / 1.45) = 29 degrees of the axis or more, over half of the 90-degree view), the side
  // walls at the edges. Textured, the end wall is read; painted, its columns miss it.
  EXPECT_EQ(flat.close_obstacles, flat.columns);
  EXPECT_EQ(rough.close_obstacles, rough.columns);
  EXPECT_LT(rough.close_misses, rough.close_obstacles / 8);
  EXPECT_GT(flat.close_misses, flat.close_obstacles / 2);
}

TEST(PathScanAccuracyTest, EveryFrameCountOfZeroIsRefused) {
  const ExplorationConfig config = loadExplorationConfig(testing::shippedExplorationConfigPath());
  EXPECT_THROW(scanAccuracyAlongPath(config, corridorEndingIn("rough"), downTheCorridor(), 0, ScanAccuracyOptions{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
