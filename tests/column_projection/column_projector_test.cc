#include "column_projection/column_projector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "test_scenes.h"

namespace stereonav {
namespace {

TEST(ColumnProjectorTest, WallAndBoxGiveTheirDisparitiesFloorAndShelfAreIgnored) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  const DisparityScan scan = ColumnProjector(rig, bodyVolume(0.95)).project(levelCorridor());
  ASSERT_EQ(scan.columns(), 201);
  for (int x = 0; x < 201; ++x) {
    const bool box = x >= 150 && x <= 160;
    // Without the body volume the floor (up to d = 10) or the shelf (8) would win everywhere.
    EXPECT_EQ(scan.column_disparity[x], box ? 8.0f : 5.0f) << "column " << x;
    // The wall enters the body volume (0.95 m) at row 28: 0.5 + (50 - 28) * 0.02 = 0.94.
    EXPECT_EQ(scan.column_row[x], box ? 40 : 28) << "column " << x;
  }
}

TEST(ColumnProjectorTest, PointsAboveTheRobotAreIgnored) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity = levelCorridor();
  disparity(cv::Rect(20, 10, 1, 91)).setTo(kInvalidDisparity);  // column 20 sees only the shelf
  // The shelf's lowest row (9) is 0.5 + 41 * 0.0125 = 1.0125 m high.
  EXPECT_FALSE(ColumnProjector(rig, bodyVolume(0.95)).project(disparity).valid(20));
  // For a 1.06 m robot, shelf rows 6..9 (0.5 + 44 * 0.0125 = 1.05 m and lower) are obstacles.
  const DisparityScan taller = ColumnProjector(rig, bodyVolume(1.06)).project(disparity);
  EXPECT_EQ(taller.column_disparity[20], 8.0f);
  EXPECT_EQ(taller.column_row[20], 6);
}

TEST(ColumnProjectorTest, TiltedCameraIgnoresTheFloorAndSeesTheBox) {
  const CameraRig rig = testRig(0, 0, 0, 30);
  const DisparityScan scan = ColumnProjector(rig, bodyVolume(1.0)).project(tiltedFloorWithBox());
  // The closest box point along the optical axis is its top edge: Z = cos30 + (0.5 - 0.3) sin30
  // = 0.9660 m, d = 10 / 0.9660 = 10.352 (the top pixel row sits a little below the edge).
  EXPECT_NEAR(scan.column_disparity[100], 10.352f, 0.1f);
  // The box is 0.4 m wide at about 1 m: columns 100 +- 20 at most. Elsewhere only floor.
  for (int x = 0; x < 201; ++x) {
    if (std::abs(x - 100) > 22) {
      EXPECT_FALSE(scan.valid(x)) << "column " << x;
    } else if (std::abs(x - 100) < 15) {
      EXPECT_TRUE(scan.valid(x)) << "column " << x;
    }
  }
}

TEST(ColumnProjectorTest, DepthPerColumnIsFocalTimesBaselineOverDisparity) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity = levelCorridor();
  disparity.col(20).setTo(kInvalidDisparity);
  const std::vector<float> depths =
      columnDepths(ColumnProjector(rig, bodyVolume(0.95)).project(disparity), rig);
  EXPECT_FLOAT_EQ(depths[0], 2.0f);     // 100 * 0.1 / 5
  EXPECT_FLOAT_EQ(depths[155], 1.25f);  // 100 * 0.1 / 8
  EXPECT_EQ(depths[20], kInvalidDisparity);
}

TEST(ColumnProjectorTest, PointsDeeperThanMaxDepthAreNoReadings) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  ProjectionOptions options = bodyVolume(0.95);
  options.max_depth_m = 1.5;  // between the box (1.25 m) and the wall (2 m)
  const DisparityScan scan = ColumnProjector(rig, options).project(levelCorridor());
  for (int x = 0; x < 201; ++x) {
    const bool box = x >= 150 && x <= 160;
    EXPECT_EQ(scan.valid(x), box) << "column " << x;
  }
  EXPECT_EQ(scan.column_disparity[155], 8.0f);
}

// Column 100 of a level camera looking at a wall 2 m away (d = 5, fB = 10): ten rows inside the
// body volume read the wall with noise, one of them far too near (6.5), and a floor pixel below
// (row 100, d = 5.5: 0.5 - 50 * 10 / 5.5 / 100 = -0.41 m high) lies outside the volume.
cv::Mat1f noisyWallColumn() {
  cv::Mat1f disparity(101, 201, kInvalidDisparity);
  const float wall[] = {5.0f, 5.2f, 4.9f, 5.15f, 6.5f, 5.05f, 4.8f, 5.3f, 5.1f, 4.95f};
  for (int i = 0; i < 10; ++i) disparity(30 + i, 100) = wall[i];
  disparity(100, 100) = 5.5f;
  return disparity;
}

TEST(ColumnProjectorTest, SurfaceBandTakesTheMedianOfTheNearestSurface) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  ProjectionOptions options = bodyVolume(0.95);
  // The paper's reading: the largest disparity, the outlier.
  DisparityScan scan = ColumnProjector(rig, options).project(noisyWallColumn());
  EXPECT_EQ(scan.column_disparity[100], 6.5f);
  EXPECT_EQ(scan.column_row[100], 34);
  // Within 2 px of it: all ten wall pixels (not the floor pixel); sorted 6.5 5.3 5.2 5.15 5.1
  // 5.05 5.0 4.95 4.9 4.8, the median (the lower middle one) is 5.05, row 35.
  options.surface_band_px = 2.0;
  scan = ColumnProjector(rig, options).project(noisyWallColumn());
  EXPECT_EQ(scan.column_disparity[100], 5.05f);
  EXPECT_EQ(scan.column_row[100], 35);
  EXPECT_TRUE(scan.column_surface.empty());
  // Within 1 px only the outlier itself.
  options.surface_band_px = 1.0;
  scan = ColumnProjector(rig, options).project(noisyWallColumn());
  EXPECT_EQ(scan.column_disparity[100], 6.5f);
  EXPECT_FALSE(scan.valid(99));
}

TEST(ColumnProjectorTest, SurfaceBandForTheScanOnlyKeepsTheNearestPointAsTheReading) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  ProjectionOptions options = bodyVolume(0.95);
  options.surface_band_px = 2.0;
  options.surface_band_scan_only = true;
  const DisparityScan scan = ColumnProjector(rig, options).project(noisyWallColumn());
  EXPECT_EQ(scan.column_disparity[100], 6.5f);
  EXPECT_EQ(scan.column_row[100], 34);
  EXPECT_EQ(scan.column_surface[100], 5.05f);
  EXPECT_EQ(scan.column_surface_row[100], 35);
  EXPECT_FALSE(isValidDisparity(scan.column_surface[99]));
  EXPECT_EQ(scan.column_surface_row[99], -1);
  // The scan a matcher reads.
  const DisparityScan surfaces = surfaceReadings(scan);
  EXPECT_EQ(surfaces.column_disparity[100], 5.05f);
  EXPECT_EQ(surfaces.column_row[100], 35);
  EXPECT_FALSE(surfaces.valid(99));
  // Without surfaces, the scan itself.
  options.surface_band_scan_only = false;
  EXPECT_EQ(surfaceReadings(ColumnProjector(rig, options).project(noisyWallColumn())).column_disparity[100], 5.05f);
}

TEST(ColumnProjectorTest, MaxDepthAppliesToTheColumnsReadingNotToItsPixels) {
  // A surface around the 2 m limit (d = 5): its median 4.95 (2.02 m) is beyond it, although two
  // of its pixels (5.05, 5.1) are nearer; the paper's largest disparity 5.1 is inside.
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity(101, 201, kInvalidDisparity);
  const float surface[] = {4.8f, 5.05f, 4.95f, 5.1f, 4.9f};
  for (int i = 0; i < 5; ++i) disparity(30 + i, 100) = surface[i];
  ProjectionOptions options = bodyVolume(0.95);
  options.max_depth_m = 2.0;
  EXPECT_EQ(ColumnProjector(rig, options).project(disparity).column_disparity[100], 5.1f);
  options.surface_band_px = 1.0;
  DisparityScan scan = ColumnProjector(rig, options).project(disparity);
  EXPECT_FALSE(scan.valid(100));
  EXPECT_EQ(scan.column_row[100], -1);
  // The nearest point kept as the reading is inside; the scan's surface is not.
  options.surface_band_scan_only = true;
  scan = ColumnProjector(rig, options).project(disparity);
  EXPECT_EQ(scan.column_disparity[100], 5.1f);
  EXPECT_FALSE(isValidDisparity(scan.column_surface[100]));
  EXPECT_EQ(scan.column_surface_row[100], -1);
}

TEST(ColumnProjectorTest, ZeroDisparityIsNoObstacle) {
  // A level ray stays at the camera's height at any depth; at d = 0 it is infinitely far.
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity(101, 201, kInvalidDisparity);
  disparity(50, 7) = 0.0f;
  disparity(50, 8) = 0.5f;
  const DisparityScan scan = ColumnProjector(rig, bodyVolume(1.0)).project(disparity);
  EXPECT_FALSE(scan.valid(7));
  EXPECT_EQ(scan.column_disparity[8], 0.5f);
}

constexpr double ProjectionOptions::*kFloorEnd = &ProjectionOptions::floor_end_max_depth_m;
constexpr double ProjectionOptions::*kFloorEndClear = &ProjectionOptions::floor_end_clear_max_depth_m;
constexpr double ProjectionOptions::*kNearFloor = &ProjectionOptions::near_floor_m;

// The body volume up to 0.95 m with one of the depth options above set.
ProjectionOptions bodyVolumeWith(double ProjectionOptions::*option, double value_m) {
  ProjectionOptions options = bodyVolume(0.95);
  options.*option = value_m;
  return options;
}

// levelCorridor() with its wall in flat paint: the wall rows (10..74) match nothing. The floor,
// d = (y - 50) / 5, ends at row 75, the wall's foot: Z = 2 m, d = 5.
cv::Mat1f unmatchedWallCorridor() {
  cv::Mat1f disparity = levelCorridor();
  disparity(cv::Rect(0, 10, 150, 65)).setTo(kInvalidDisparity);
  disparity(cv::Rect(161, 10, 40, 65)).setTo(kInvalidDisparity);
  return disparity;
}

TEST(ColumnProjectorTest, AnUnmatchedWallIsReadAtTheFloorsEnd) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  const DisparityScan off = ColumnProjector(rig, bodyVolume(0.95)).project(unmatchedWallCorridor());
  EXPECT_FALSE(off.valid(20));  // the paper's projection sees nothing there
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kFloorEnd, 3.0)).project(unmatchedWallCorridor());
  for (int x = 0; x < 201; ++x) {
    const bool box = x >= 150 && x <= 160;
    // The foot on the floor plane: row 75 is 25 rows below the centre, Z = 0.5 * 100 / 25 = 2 m.
    EXPECT_EQ(scan.column_disparity[x], box ? 8.0f : 5.0f) << "column " << x;
    EXPECT_EQ(scan.column_row[x], box ? 40 : 75) << "column " << x;
  }
  // The foot is where the painted wall's surface lies too; the box keeps its own.
  ProjectionOptions band = bodyVolumeWith(kFloorEnd, 3.0);
  band.surface_band_px = 1.0;
  band.surface_band_scan_only = true;
  const DisparityScan surfaces = ColumnProjector(rig, band).project(unmatchedWallCorridor());
  EXPECT_EQ(surfaces.column_surface[20], 5.0f);
  EXPECT_EQ(surfaces.column_surface_row[20], 75);
  EXPECT_EQ(surfaces.column_surface[155], 8.0f);
}

TEST(ColumnProjectorTest, AFloorEndFartherThanTheLimitIsNoFoot) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  EXPECT_FALSE(ColumnProjector(rig, bodyVolumeWith(kFloorEnd, 1.9)).project(unmatchedWallCorridor()).valid(20));
}

TEST(ColumnProjectorTest, AGapInTheFloorsTextureIsNoFoot) {
  // Rows 78..82 of the floor match nothing, and the textured wall stands behind: the reading is
  // the wall (d = 5), not a foot at the gap's near edge (row 83, d = 6.6).
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity = levelCorridor();
  disparity(cv::Rect(0, 78, 201, 5)).setTo(kInvalidDisparity);
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kFloorEnd, 3.0)).project(disparity);
  EXPECT_EQ(scan.column_disparity[20], 5.0f);
  EXPECT_EQ(scan.column_row[20], 28);
}

// levelCorridor() with a flat-painted box 0.3 m high at Z = 1.25 m in columns 100..120: rows
// 66..90 (heights 0.3 down to 0 at that depth) match nothing; the textured wall (d = 5) shows
// above it.
cv::Mat1f paintedBoxCorridor() {
  cv::Mat1f disparity = levelCorridor();
  disparity(cv::Rect(100, 66, 21, 25)).setTo(kInvalidDisparity);
  return disparity;
}

TEST(ColumnProjectorTest, ALowUnmatchedBoxBeforeATexturedWallIsReadAtItsFoot) {
  // A flat-painted box 0.3 m high at Z = 1.25 m in columns 100..120: rows 66..90 (heights 0.3
  // down to 0 at that depth) match nothing; the textured wall (d = 5) shows above it. The floor
  // ends at row 91 (Z = 50 / 41 = 1.22 m, d = 8.2), the box's foot to within a row.
  const CameraRig rig = testRig(0, 0, 0, 0);
  const cv::Mat1f disparity = paintedBoxCorridor();
  const DisparityScan without = ColumnProjector(rig, bodyVolume(0.95)).project(disparity);
  EXPECT_EQ(without.column_disparity[110], 5.0f);  // the wall behind: the box is not seen
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kFloorEnd, 3.0)).project(disparity);
  EXPECT_FLOAT_EQ(scan.column_disparity[110], 8.2f);
  EXPECT_EQ(scan.column_row[110], 91);
  EXPECT_EQ(scan.column_disparity[90], 5.0f);  // beside the box, the wall
}

TEST(ColumnProjectorTest, AFloorEndBeforeTheReadingEndsItsClear) {
  // The painted box of the case above: the reading stays the wall behind it (d = 5), and its
  // CLEAR ends at the box's foot, row 91 (d = 8.2). Beside the box the floor runs to the wall:
  // nothing to end.
  const CameraRig rig = testRig(0, 0, 0, 0);
  const cv::Mat1f disparity = paintedBoxCorridor();
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kFloorEndClear, 3.0)).project(disparity);
  EXPECT_EQ(scan.column_disparity[110], 5.0f);
  EXPECT_TRUE(scan.endsClear(110));
  EXPECT_FLOAT_EQ(scan.column_clear_end[110], 8.2f);
  EXPECT_EQ(scan.column_clear_end_row[110], 91);
  EXPECT_FALSE(scan.endsClear(90));
  // Farther than the limit (Z = 1.22 m) the foot is not looked for.
  EXPECT_FALSE(ColumnProjector(rig, bodyVolumeWith(kFloorEndClear, 1.0)).project(disparity).endsClear(110));
}

TEST(ColumnProjectorTest, AFarGhostOnAnUnmatchedWallKeepsItsClearToTheWallsFoot) {
  // The flat-painted wall at Z = 2 m (foot at row 75, d = 5), a few of its pixels in column 20
  // matched at d = 2 (a textured surface far behind, in the window of pixels beside it): the
  // reading is that ghost, 5 m deep, but its CLEAR stops at the wall's foot. A column without a
  // reading (30) has its foot all the same: the guard stops short of it.
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity = unmatchedWallCorridor();
  disparity(cv::Rect(20, 45, 1, 3)).setTo(2.0f);  // 0.65-0.75 m high at Z = 5 m
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kFloorEndClear, 3.0)).project(disparity);
  EXPECT_EQ(scan.column_disparity[20], 2.0f);
  EXPECT_FLOAT_EQ(scan.column_clear_end[20], 5.0f);
  EXPECT_EQ(scan.column_clear_end_row[20], 75);
  EXPECT_FALSE(scan.valid(30));
  EXPECT_TRUE(scan.endsClear(30));
  EXPECT_FLOAT_EQ(scan.column_clear_end[30], 5.0f);
}

// In levelCorridor() the nearest floor the camera sees is the bottom row's, Z = 50 / (100 - 50)
// = 1 m; with near_floor_m = 0.25 the rows to check are those whose floor lies at Z <= 1.25 m,
// 50 / (y - 50) <= 1.25: rows 90..100, eleven of them.
TEST(ColumnProjectorTest, AColumnThatMatchesNoneOfTheNearestFloorIsBlind) {
  const CameraRig rig = testRig(0, 0, 0, 0);
  cv::Mat1f disparity = levelCorridor();
  EXPECT_TRUE(ColumnProjector(rig, bodyVolume(0.95)).project(disparity).column_blind.empty());  // off
  disparity(cv::Rect(30, 92, 11, 9)).setTo(kInvalidDisparity);   // 9 of the 11 rows: blind
  disparity(cv::Rect(60, 95, 11, 6)).setTo(kInvalidDisparity);   // 6 of 11: a gap in the texture
  disparity(cv::Rect(120, 0, 5, 101)).setTo(kInvalidDisparity);  // nothing at all
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kNearFloor, 0.25)).project(disparity);
  ASSERT_EQ(scan.column_blind.size(), 201u);
  for (int x = 0; x < 201; ++x) {
    const bool blind = (x >= 30 && x <= 40) || (x >= 120 && x <= 124);
    EXPECT_EQ(scan.blind(x), blind) << "column " << x;
  }
  // The readings are those of the paper's projection: a blind column tells nothing of depth.
  EXPECT_EQ(scan.column_disparity[35], 5.0f);
  EXPECT_FALSE(scan.valid(122));
  // With a deeper band (Z <= 2: rows 75..100, 26 rows) the same 9 unmatched rows are a gap.
  EXPECT_FALSE(ColumnProjector(rig, bodyVolumeWith(kNearFloor, 1.0)).project(disparity).blind(35));
}

TEST(ColumnProjectorTest, NoColumnIsBlindWithoutFloorInSight) {
  // Tilted 60 degrees up, the camera sees no floor at all: nothing to miss.
  const CameraRig rig = testRig(0, 0, 0, -60);
  const DisparityScan scan = ColumnProjector(rig, bodyVolumeWith(kNearFloor, 0.25)).project(cv::Mat1f(101, 201, kInvalidDisparity));
  for (int x = 0; x < 201; ++x) EXPECT_FALSE(scan.blind(x)) << "column " << x;
}

TEST(ColumnProjectorTest, RejectsImageOfTheWrongSize) {
  const ColumnProjector projector(testRig(0, 0, 0, 0), bodyVolume(1.0));
  EXPECT_THROW(projector.project(cv::Mat1f(120, 160, 5.0f)), std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
