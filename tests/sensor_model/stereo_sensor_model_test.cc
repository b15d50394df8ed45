#include "sensor_model/stereo_sensor_model.h"

#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace stereonav {
namespace {

using Cells = std::set<std::pair<int, int>>;  // (col, row)

// A grid whose cell centres sit on integer world coordinates: cell (col, row) is centred at
// (col - 20, row - 20), so the hand computations below work in plain metres.
const GridFrame kUnitGrid{-20.5, -20.5, 1.0};
std::pair<int, int> cellAt(int x, int y) { return {x + 20, y + 20}; }

DisparityScanCamera camera(double focal_px, double cx, double baseline_m,
                           const mrpt::poses::CPose3D& pose_on_robot =
                               CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0)) {
  DisparityScanCamera c;
  c.focal_px = focal_px;
  c.cx = cx;
  c.baseline_m = baseline_m;
  c.pose_on_robot = pose_on_robot;
  return c;
}

DisparityScan scanOf(std::vector<float> disparities) {
  DisparityScan scan;
  scan.column_disparity = std::move(disparities);
  return scan;
}

struct RasterCells {
  Cells clear;
  Cells occupied;
};

RasterCells rasterCells(const StereoSensorModel& model, const DisparityScanCamera& cam,
                        const DisparityScan& scan, const mrpt::poses::CPose2D& robot_pose,
                        const GridFrame& frame = kUnitGrid) {
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  ScanRaster raster;
  model.rasterize(readings, robot_pose + cameraFloorPose(cam.pose_on_robot), frame, raster);
  RasterCells cells;
  for (size_t i = raster.clear_begin; i < raster.spans.size(); ++i) {
    const CellSpan& s = raster.spans[i];
    for (int col = s.col_begin; col < s.col_end; ++col) cells.clear.insert({col, s.row});
  }
  for (const ReadingSpans& reading : raster.readings) {
    for (uint32_t i = reading.occupied_begin; i < reading.occupied_end; ++i) {
      const CellSpan& s = raster.spans[i];
      for (int col = s.col_begin; col < s.col_end; ++col) cells.occupied.insert({col, s.row});
    }
  }
  return cells;
}

TEST(StereoSensorModelTest, TrapezoidCornersFollowEquationOne) {
  // f = 100 px, B = 0.1 m, d = 10: Z(10.5) = 10/10.5 = 0.952381 m, Z(9.5) = 10/9.5 = 1.052632 m.
  const DisparityScanCamera cam = camera(100.0, 50.0, 0.1);
  const StereoSensorModel model(SensorModelOptions{});
  const ColumnReading centre = model.readingForDisparity(50, 10.0f, cam);
  EXPECT_NEAR(centre.near_depth_m, 0.9523809524, 1e-9);
  EXPECT_NEAR(centre.far_depth_m, 1.0526315789, 1e-9);

  // Column 60 (10 px right of the principal point): X = (x - cx -/+ 0.5) Z / f, i.e. 9.5 Z/100
  // and 10.5 Z/100 to the image right = the robot's right (-y) in the camera floor frame.
  const ColumnReading right = model.readingForDisparity(60, 10.0f, cam);
  const RegionCorners c = model.corners(right, mrpt::poses::CPose2D());
  const double zn = 10.0 / 10.5, zf = 10.0 / 9.5;
  EXPECT_NEAR(c.near_left.x, zn, 1e-12);
  EXPECT_NEAR(c.near_left.y, -9.5 * zn / 100.0, 1e-12);
  EXPECT_NEAR(c.near_right.x, zn, 1e-12);
  EXPECT_NEAR(c.near_right.y, -10.5 * zn / 100.0, 1e-12);
  EXPECT_NEAR(c.far_left.x, zf, 1e-12);
  EXPECT_NEAR(c.far_left.y, -9.5 * zf / 100.0, 1e-12);
  EXPECT_NEAR(c.far_right.x, zf, 1e-12);
  EXPECT_NEAR(c.far_right.y, -10.5 * zf / 100.0, 1e-12);
}

TEST(StereoSensorModelTest, DisparityAtMostHalfAPixelReachesMaxRange) {
  const DisparityScanCamera cam = camera(100.0, 50.0, 0.1);  // fB = 10
  SensorModelOptions options;
  options.max_range_m = 30.0;
  const StereoSensorModel model(options);
  const ColumnReading half = model.readingForDisparity(50, 0.5f, cam);
  EXPECT_DOUBLE_EQ(half.near_depth_m, 10.0);  // Z(1.0)
  EXPECT_DOUBLE_EQ(half.far_depth_m, 30.0);
  const ColumnReading zero = model.readingForDisparity(50, 0.0f, cam);
  EXPECT_DOUBLE_EQ(zero.near_depth_m, 20.0);  // Z(0.5)
  EXPECT_DOUBLE_EQ(zero.far_depth_m, 30.0);
  // Just above half a pixel, Z(d - 0.5) = 10 / 0.01 = 1000 m: the region stops at max range.
  const ColumnReading just_above = model.readingForDisparity(50, 0.51f, cam);
  EXPECT_NEAR(just_above.near_depth_m, 10.0 / 1.01, 1e-6);
  EXPECT_DOUBLE_EQ(just_above.far_depth_m, 30.0);
  // Beyond max range there is no OCC region, only CLEAR.
  options.max_range_m = 15.0;
  EXPECT_FALSE(StereoSensorModel(options).readingForDisparity(50, 0.0f, cam).hasOccupiedRegion());
}

TEST(StereoSensorModelTest, InvalidColumnsClearNothingUnlessAsked) {
  const DisparityScanCamera cam = camera(1.0, 0.0, 4.0);
  const DisparityScan scan = scanOf({kInvalidDisparity});
  std::vector<ColumnReading> readings;
  StereoSensorModel(SensorModelOptions{}).readings(scan, cam, readings);
  EXPECT_TRUE(readings.empty());

  SensorModelOptions options;
  options.clear_invalid_columns_to_m = 3.3;
  const StereoSensorModel clearing(options);
  clearing.readings(scan, cam, readings);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_FALSE(readings[0].hasOccupiedRegion());
  // Wedge |y| <= x/2 out to depth 3.3 from the origin: centres x = 0 (apex), 1 (|y| <= 0.5),
  // 2 (|y| <= 1, both edges are in as the wedge lies right of them), 3 (|y| <= 1.5).
  const RasterCells cells = rasterCells(clearing, cam, scan, mrpt::poses::CPose2D());
  EXPECT_TRUE(cells.occupied.empty());
  EXPECT_EQ(cells.clear, (Cells{cellAt(0, 0), cellAt(1, 0), cellAt(2, -1), cellAt(2, 0),
                                cellAt(2, 1), cellAt(3, -1), cellAt(3, 0), cellAt(3, 1)}));
}

TEST(StereoSensorModelTest, AClearEndStopsClearButNotOcc) {
  // f = 1, cx = 0, fB = 4, a level head: the wedge |y| <= x/2; d = 0.5 gives CLEAR [0, Z(1) = 4)
  // and OCC [4, max_range_m = 6). A floor end at d = 1.6 (2.5 m) keeps CLEAR to the centres
  // x = 0, 1, 2; the row x = 3 (|y| <= 1.5) gets no update at all, and OCC stays where
  // equation 1 puts it.
  const DisparityScanCamera cam = camera(1.0, 0.0, 4.0);
  DisparityScan scan = scanOf({0.5f});
  SensorModelOptions options;
  options.max_range_m = 6.0;
  const StereoSensorModel model(options);
  const RasterCells full = rasterCells(model, cam, scan, mrpt::poses::CPose2D());
  scan.column_clear_end = {1.6f};
  scan.column_clear_end_row = {30};
  const RasterCells cut = rasterCells(model, cam, scan, mrpt::poses::CPose2D());
  const Cells near_clear{cellAt(0, 0), cellAt(1, 0), cellAt(2, -1), cellAt(2, 0), cellAt(2, 1)};
  EXPECT_EQ(cut.clear, near_clear);
  Cells full_clear = near_clear;
  for (int y = -1; y <= 1; ++y) full_clear.insert(cellAt(3, y));
  EXPECT_EQ(full.clear, full_clear);
  EXPECT_EQ(cut.occupied, full.occupied);
  EXPECT_EQ(full.occupied.count(cellAt(4, 0)), 1u);
}

TEST(StereoSensorModelTest, AReadingAtTheMatchersRangeTopUpdatesNothing) {
  // f = 1, cx = 0, fB = 4, a level head: columns 0 and 1 span -1.5 x <= y <= 0.5 x. d = 1.5 in
  // both gives CLEAR for x in [0, Z(2) = 2) and OCC for x in [2, Z(1) = 4): the cell centred at
  // (1, 0) is CLEAR, the one at (3, 0) OCC. With the matcher's range top at 1.5 the surface may
  // lie anywhere nearer than Z(1.5), so neither region is where it is: no reading, no cell. A
  // range top above the readings (2) changes nothing; column 1 read at it is dropped alone.
  const DisparityScanCamera cam = camera(1.0, 0.0, 4.0);
  DisparityScan scan = scanOf({1.5f, 1.5f});
  const StereoSensorModel model{SensorModelOptions{}};
  const RasterCells measured = rasterCells(model, cam, scan, mrpt::poses::CPose2D());
  EXPECT_EQ(measured.clear.count(cellAt(1, 0)), 1u);
  EXPECT_EQ(measured.occupied.count(cellAt(3, 0)), 1u);

  scan.range_top = 1.5f;
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  EXPECT_TRUE(readings.empty());
  const RasterCells bounded = rasterCells(model, cam, scan, mrpt::poses::CPose2D());
  EXPECT_TRUE(bounded.clear.empty());
  EXPECT_TRUE(bounded.occupied.empty());

  scan.range_top = 2.0f;
  const RasterCells below_top = rasterCells(model, cam, scan, mrpt::poses::CPose2D());
  EXPECT_EQ(below_top.clear, measured.clear);
  EXPECT_EQ(below_top.occupied, measured.occupied);

  scan.column_disparity = {1.0f, 2.0f};
  model.readings(scan, cam, readings);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_EQ(readings[0].column, 0);
}

TEST(StereoSensorModelTest, CellsOnRegionBoundariesFollowTheHalfOpenRule) {
  // One column, f = 1, cx = 0: the lines of sight are y = +x/2 (image left) and y = -x/2.
  // fB = 4 and d = 1.5: near depth 4/2 = 2, far depth 4/1 = 4. The camera is at the origin
  // looking along +x, so cell centres (integers) fall exactly on every edge:
  //  - near edge x = 2: OCC lies right of it -> (2, y) is OCC, never CLEAR;
  //  - far edge x = 4: OCC lies left of it -> (4, y) is out;
  //  - rays at (2, +-1): the wedge lies right of both -> in.
  const DisparityScanCamera cam = camera(1.0, 0.0, 4.0);
  const RasterCells cells =
      rasterCells(StereoSensorModel(SensorModelOptions{}), cam, scanOf({1.5f}),
                  mrpt::poses::CPose2D());
  EXPECT_EQ(cells.occupied, (Cells{cellAt(2, -1), cellAt(2, 0), cellAt(2, 1), cellAt(3, -1),
                                   cellAt(3, 0), cellAt(3, 1)}));
  EXPECT_EQ(cells.clear, (Cells{cellAt(0, 0), cellAt(1, 0)}));
}

TEST(StereoSensorModelTest, CameraFloorPoseComesFromTheOpticalFrame) {
  const mrpt::poses::CPose2D floor = cameraFloorPose(
      CameraRig::opticalPoseOnRobot(0.2, -0.3, 0.6, mrpt::DEG2RAD(30.0), 0.0));
  EXPECT_NEAR(floor.x(), 0.2, 1e-12);
  EXPECT_NEAR(floor.y(), -0.3, 1e-12);
  EXPECT_NEAR(floor.phi(), mrpt::DEG2RAD(30.0), 1e-12);
}

// Hand geometry for an offset camera: f = 1, cx = 0.13 (so the lines of sight through the pixel
// edges -0.5 and +0.5 have lateral slopes -0.63 and +0.37: the wedge spans 0.63 x to the left
// and 0.37 x to the right of the optical axis), fB = 3.3 and d = 1: near depth 3.3/1.5 = 2.2,
// far depth 3.3/0.5 = 6.6. The camera sits at (0.2, -0.3) on the robot, turned by `mount_yaw`.
struct OffsetCase {
  DisparityScanCamera cam = camera(1.0, 0.13, 3.3,
                                   CameraRig::opticalPoseOnRobot(0.2, -0.3, 0.5, 0.0, 0.0));
  DisparityScan scan = scanOf({1.0f});
};

// Robot at (0.1, 0.5) heading 0: the camera is at (0.3, 0.2) looking along +x. Cell centres
// (X, Y), depth a = X - 0.3, lateral b = Y - 0.2 (left positive):
//   CLEAR: 0 <= a < 2.2 and -0.37 a <= b <= 0.63 a
//     X = 1: a = 0.7, b in [-0.259, 0.441]  -> Y = 0
//     X = 2: a = 1.7, b in [-0.629, 1.071]  -> Y = 0, 1
//   OCC: 2.2 <= a < 6.6
//     X = 3: a = 2.7, b in [-0.999, 1.701]  -> Y = 0, 1
//     X = 4: a = 3.7, b in [-1.369, 2.331]  -> Y = -1 .. 2
//     X = 5: a = 4.7, b in [-1.739, 2.961]  -> Y = -1 .. 3
//     X = 6: a = 5.7, b in [-2.109, 3.591]  -> Y = -1 .. 3
TEST(StereoSensorModelTest, CellsForAnOffsetCameraByHand) {
  const OffsetCase c;
  const RasterCells cells = rasterCells(StereoSensorModel(SensorModelOptions{}), c.cam, c.scan,
                                        mrpt::poses::CPose2D(0.1, 0.5, 0.0));
  EXPECT_EQ(cells.clear, (Cells{cellAt(1, 0), cellAt(2, 0), cellAt(2, 1)}));
  Cells occupied{cellAt(3, 0), cellAt(3, 1)};
  for (int y = -1; y <= 2; ++y) occupied.insert(cellAt(4, y));
  for (int x = 5; x <= 6; ++x) {
    for (int y = -1; y <= 3; ++y) occupied.insert(cellAt(x, y));
  }
  EXPECT_EQ(cells.occupied, occupied);
}

// Robot at (0, 0) heading +90 deg: the camera offset (0.2, -0.3) turns into (0.3, 0.2) in the
// world and it looks along +y; image-left is now -x. Depth a = Y - 0.2, lateral b = 0.3 - X:
//   CLEAR: Y = 1: a = 0.8, b in [-0.296, 0.504] -> X in [-0.204, 0.596] -> X = 0
//          Y = 2: a = 1.8, b in [-0.666, 1.134] -> X in [-0.834, 0.966] -> X = 0
//   OCC:   Y = 3: a = 2.8, b in [-1.036, 1.764] -> X in [-1.464, 1.336] -> X = -1 .. 1
//          Y = 4: a = 3.8, b in [-1.406, 2.394] -> X in [-2.094, 1.706] -> X = -2 .. 1
//          Y = 5: a = 4.8, b in [-1.776, 3.024] -> X in [-2.724, 2.076] -> X = -2 .. 2
//          Y = 6: a = 5.8, b in [-2.146, 3.654] -> X in [-3.354, 2.446] -> X = -3 .. 2
TEST(StereoSensorModelTest, CellsForARobotTurnedNinetyDegreesByHand) {
  const OffsetCase c;
  const RasterCells cells = rasterCells(StereoSensorModel(SensorModelOptions{}), c.cam, c.scan,
                                        mrpt::poses::CPose2D(0.0, 0.0, mrpt::DEG2RAD(90.0)));
  EXPECT_EQ(cells.clear, (Cells{cellAt(0, 1), cellAt(0, 2)}));
  Cells occupied;
  for (int x = -1; x <= 1; ++x) occupied.insert(cellAt(x, 3));
  for (int x = -2; x <= 1; ++x) occupied.insert(cellAt(x, 4));
  for (int x = -2; x <= 2; ++x) occupied.insert(cellAt(x, 5));
  for (int x = -3; x <= 2; ++x) occupied.insert(cellAt(x, 6));
  EXPECT_EQ(cells.occupied, occupied);
}

// Independent membership test: cross products against the corners computed here by hand.
bool insideConvex(const std::vector<mrpt::math::TPoint2D>& ccw, double x, double y) {
  for (size_t i = 0; i < ccw.size(); ++i) {
    const auto& a = ccw[i];
    const auto& b = ccw[(i + 1) % ccw.size()];
    if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) < 0) return false;
  }
  return true;
}

TEST(StereoSensorModelTest, CellsForARobotTurnedFortyFiveDegrees) {
  // Robot at (0.05, -0.15) heading 45 deg, so the camera (0.2, -0.3 on the robot) is at
  // (0.05 + (0.2 + 0.3) / sqrt 2, -0.15 + (0.2 - 0.3) / sqrt 2) looking along (1, 1)/sqrt 2.
  const OffsetCase c;
  const double h = std::sqrt(0.5);
  const double cam_x = 0.05 + 0.5 * h, cam_y = -0.15 - 0.1 * h;
  const auto world = [&](double depth, double left) {  // camera (depth, left) -> world
    return mrpt::math::TPoint2D(cam_x + depth * h - left * h, cam_y + depth * h + left * h);
  };
  // Lateral offsets to the left are 0.63 a (image-left edge) and -0.37 a (image-right edge).
  const auto near_left = world(2.2, 0.63 * 2.2), near_right = world(2.2, -0.37 * 2.2);
  const auto far_left = world(6.6, 0.63 * 6.6), far_right = world(6.6, -0.37 * 6.6);
  const std::vector<mrpt::math::TPoint2D> clear{world(0, 0), near_right, near_left};
  const std::vector<mrpt::math::TPoint2D> occupied{near_right, far_right, far_left, near_left};

  const RasterCells cells =
      rasterCells(StereoSensorModel(SensorModelOptions{}), c.cam, c.scan,
                  mrpt::poses::CPose2D(0.05, -0.15, mrpt::DEG2RAD(45.0)));
  Cells expected_clear, expected_occupied;
  for (int x = -20; x <= 20; ++x) {
    for (int y = -20; y <= 20; ++y) {
      if (insideConvex(clear, x, y)) expected_clear.insert(cellAt(x, y));
      if (insideConvex(occupied, x, y)) expected_occupied.insert(cellAt(x, y));
    }
  }
  EXPECT_EQ(cells.clear, expected_clear);
  EXPECT_EQ(cells.occupied, expected_occupied);
  EXPECT_GE(expected_occupied.size(), 15u);  // a real region, not an empty match
}

TEST(StereoSensorModelTest, AScanTilesItsWedgesWithoutOverlapsOrGaps) {
  // 64 columns, all at the same disparity, seen from a rotated pose on a fine grid: the cells of
  // all readings' regions must be disjoint and together equal the whole fan cut at the near
  // (CLEAR) and far (OCC) depths, which is checked cell by cell against the fan's corners.
  DisparityScanCamera cam = camera(40.0, 31.5, 0.1);  // fB = 4
  DisparityScan scan;
  scan.column_disparity.assign(64, 2.0f);  // near 4/2.5 = 1.6, far 4/1.5 = 2.667
  const StereoSensorModel model(SensorModelOptions{});
  const mrpt::poses::CPose2D robot(0.013, 0.021, mrpt::DEG2RAD(101.0));
  const GridFrame fine{-5.0, -5.0, 0.05};
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  ScanRaster raster;
  const mrpt::poses::CPose2D camera_pose = robot + cameraFloorPose(cam.pose_on_robot);
  model.rasterize(readings, camera_pose, fine, raster);

  std::map<std::pair<int, int>, int> hits;
  size_t occupied_cells = 0;
  for (size_t i = 0; i < raster.spans.size(); ++i) {
    const CellSpan& s = raster.spans[i];
    for (int col = s.col_begin; col < s.col_end; ++col) ++hits[{col, s.row}];
    if (i < raster.clear_begin) occupied_cells += s.col_end - s.col_begin;
  }
  for (const auto& [cell, count] : hits) EXPECT_EQ(count, 1) << cell.first << "," << cell.second;

  // The fan: camera, then the far corners of every column from image right to image left.
  const RegionCorners rightmost = model.corners(readings.back(), camera_pose);
  const RegionCorners leftmost = model.corners(readings.front(), camera_pose);
  const std::vector<mrpt::math::TPoint2D> fan{
      {camera_pose.x(), camera_pose.y()}, rightmost.far_right, leftmost.far_left};
  // All far edges lie on the same depth line, so the union of the regions is exactly the fan.
  size_t inside_fan = 0;
  for (int row = 0; row < 200; ++row) {
    for (int col = 0; col < 200; ++col) {
      const double x = fine.origin_x + (col + 0.5) * fine.resolution;
      const double y = fine.origin_y + (row + 0.5) * fine.resolution;
      const bool inside = insideConvex(fan, x, y);
      inside_fan += inside ? 1 : 0;
      EXPECT_EQ(inside, hits.count({col, row}) == 1) << "cell " << col << "," << row;
    }
  }
  EXPECT_EQ(inside_fan, hits.size());
  EXPECT_GT(occupied_cells, 1000u);
}

// A head tilted down by 30 degrees (cos 0.8660254, sin 0.5): f = 100 px, principal point (50, 40),
// fB = 10. The pixel at row y and depth Z lies Z (cos t - v sin t) ahead of the camera's floor
// point, v = (y - cy) / f, and Z (x - cx) / f to the image right.
DisparityScanCamera tiltedCamera() {
  DisparityScanCamera cam = camera(100.0, 50.0, 0.1,
                                   CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0,
                                                                 mrpt::DEG2RAD(30.0)));
  cam.cy = 40.0;
  return cam;
}

DisparityScan scanWithRows(int columns, const std::vector<std::pair<int, int>>& column_rows,
                           float disparity) {
  DisparityScan scan;
  scan.column_disparity.assign(columns, kInvalidDisparity);
  scan.column_row.assign(columns, -1);
  for (const auto& [column, row] : column_rows) {
    scan.column_disparity[column] = disparity;
    scan.column_row[column] = row;
  }
  return scan;
}

TEST(StereoSensorModelTest, TiltedHeadPlacesCornersByTheirRow) {
  // Column 60, row 20 (v = -0.2: floor_per_depth = 0.8660254 + 0.2 * 0.5 = 0.9660254), d = 10:
  // depths 10/10.5 = 0.952381 and 10/9.5 = 1.052632 m, forward 0.920024 and 1.016869 m; to the
  // image right (-y) 0.095 and 0.105 times the depth.
  const DisparityScanCamera cam = tiltedCamera();
  const StereoSensorModel model(SensorModelOptions{});
  const ColumnReading reading = model.readingForDisparity(60, 10.0f, cam, 20);
  EXPECT_NEAR(reading.floor_per_depth, 0.9660254038, 1e-9);
  const RegionCorners c = model.corners(reading, mrpt::poses::CPose2D());
  EXPECT_NEAR(c.near_left.x, 0.9200241941, 1e-9);
  EXPECT_NEAR(c.near_left.y, -0.0904761905, 1e-9);
  EXPECT_NEAR(c.near_right.x, 0.9200241941, 1e-9);
  EXPECT_NEAR(c.near_right.y, -0.1, 1e-9);
  EXPECT_NEAR(c.far_left.x, 1.0168688461, 1e-9);
  EXPECT_NEAR(c.far_left.y, -0.1, 1e-9);
  EXPECT_NEAR(c.far_right.x, 1.0168688461, 1e-9);
  EXPECT_NEAR(c.far_right.y, -0.1105263158, 1e-9);

  // The same corners by MRPT: the optical-frame point Z (u, v, 1) taken to the robot frame.
  const auto onFloor = [&](double edge_x, double depth) {
    const mrpt::math::TPoint3D p = cam.pose_on_robot.composePoint(
        {depth * (edge_x - 50.0) / 100.0, depth * (20.0 - 40.0) / 100.0, depth});
    return mrpt::math::TPoint2D(p.x - cam.pose_on_robot.x(), p.y - cam.pose_on_robot.y());
  };
  EXPECT_NEAR((c.near_left - onFloor(59.5, 10.0 / 10.5)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((c.far_right - onFloor(60.5, 10.0 / 9.5)).norm(), 0.0, 1e-9);

  // Without a row the reading counts as seen in the optical axis' row: forward = depth cos t.
  EXPECT_NEAR(model.readingForDisparity(60, 10.0f, cam).floor_per_depth, 0.8660254038, 1e-9);
}

TEST(StereoSensorModelTest, LevelHeadIgnoresRows) {
  const DisparityScanCamera cam = camera(100.0, 50.0, 0.1);
  const StereoSensorModel model(SensorModelOptions{});
  const RegionCorners without = model.corners(model.readingForDisparity(60, 10.0f, cam),
                                              mrpt::poses::CPose2D());
  const RegionCorners with = model.corners(model.readingForDisparity(60, 10.0f, cam, 3),
                                           mrpt::poses::CPose2D());
  // (To rounding: MRPT's level optical pose has a tilt of 6e-17 rad.)
  EXPECT_NEAR((with.near_left - without.near_left).norm(), 0.0, 1e-15);
  EXPECT_NEAR((with.far_right - without.far_right).norm(), 0.0, 1e-15);
}

TEST(StereoSensorModelTest, ScanWithoutRowsOnATiltedHeadUsesTheOpticalAxisRow) {
  const DisparityScanCamera cam = tiltedCamera();
  const StereoSensorModel model(SensorModelOptions{});
  DisparityScan scan = scanWithRows(100, {{60, 20}}, 10.0f);
  scan.column_row.clear();
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_NEAR(readings[0].nearDistance(), 10.0 / 10.5 * 0.8660254038, 1e-9);
  EXPECT_NEAR(readings[0].left_slope, 0.095 / 0.8660254038, 1e-9);
  EXPECT_NEAR(readings[0].right_slope, 0.105 / 0.8660254038, 1e-9);
}

TEST(StereoSensorModelTest, AdjacentColumnsInDifferentRowsShareTheNearerOnesRay) {
  // Columns 60 (row 20, floor_per_depth 0.9660254) and 61 (row 60, 0.7660254), both d = 10:
  // column 61 is nearer (0.952381 * 0.7660254 = 0.729548 m against 0.920024 m), so the edge
  // x = 60.5 takes its slope 0.105 / 0.7660254 = 0.137071; the outer edges keep their own:
  // 0.095 / 0.9660254 = 0.098341 and 0.115 / 0.7660254 = 0.150126.
  const DisparityScanCamera cam = tiltedCamera();
  const StereoSensorModel model(SensorModelOptions{});
  std::vector<ColumnReading> readings;
  model.readings(scanWithRows(100, {{60, 20}, {61, 60}}, 10.0f), cam, readings);
  ASSERT_EQ(readings.size(), 2u);
  EXPECT_NEAR(readings[0].left_slope, 0.0983410991, 1e-9);
  EXPECT_NEAR(readings[0].right_slope, 0.1370711722, 1e-9);
  EXPECT_EQ(readings[1].left_slope, readings[0].right_slope);
  EXPECT_NEAR(readings[1].right_slope, 0.1501255695, 1e-9);
}

TEST(StereoSensorModelTest, AFartherColumnOnTheWrongSideOfANearerRayIsEmpty) {
  // Column 59 in row 60 is nearer (0.729548 m) than columns 60..62 in row 20 (0.920024 m). Its
  // right edge x = 59.5 has slope 0.095 / 0.7660254 = 0.124017, right of columns 60 (own wedge
  // 0.098341..0.108693) and 61 (0.108693..0.119045): they keep the image order only as empty
  // wedges, and column 62 (own 0.119045..0.129397) starts at 0.124017.
  const DisparityScanCamera cam = tiltedCamera();
  const StereoSensorModel model(SensorModelOptions{});
  const DisparityScan scan = scanWithRows(100, {{59, 60}, {60, 20}, {61, 20}, {62, 20}}, 10.0f);
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  ASSERT_EQ(readings.size(), 4u);
  EXPECT_NEAR(readings[0].left_slope, 0.085 / 0.7660254038, 1e-9);
  EXPECT_NEAR(readings[0].right_slope, 0.1240167748, 1e-9);
  for (int i = 1; i <= 2; ++i) {
    EXPECT_EQ(readings[i].left_slope, readings[0].right_slope) << "column " << 59 + i;
    EXPECT_EQ(readings[i].right_slope, readings[0].right_slope) << "column " << 59 + i;
    EXPECT_FALSE(readings[i].hasOccupiedRegion());
  }
  EXPECT_EQ(readings[3].left_slope, readings[0].right_slope);
  EXPECT_NEAR(readings[3].right_slope, 0.125 / 0.9660254038, 1e-9);

  // The empty wedges add no OCC cells.
  const GridFrame fine{-0.5, -1.0, 0.01};
  ScanRaster raster;
  model.rasterize(readings, mrpt::poses::CPose2D(), fine, raster);
  EXPECT_EQ(raster.readings[1].occupied_begin, raster.readings[1].occupied_end);  // column 61
  EXPECT_EQ(raster.readings[2].occupied_begin, raster.readings[2].occupied_end);  // column 60
  EXPECT_GT(raster.readings[0].occupied_end, raster.readings[0].occupied_begin);  // column 62
}

TEST(StereoSensorModelTest, TiltedScanWithJumpingRowsTilesWithoutOverlaps) {
  // Rows jump between columns as on real scans; disparities vary too. Every cell of the scan's
  // regions must come once, each reading's OCC cells must lie in its own trapezoid (checked
  // against its corners), and the image order of the edges must hold.
  const DisparityScanCamera cam = tiltedCamera();
  const StereoSensorModel model(SensorModelOptions{});
  DisparityScan scan;
  for (int column = 0; column < 100; ++column) {
    const bool gap = column % 17 == 5;
    scan.column_disparity.push_back(gap ? kInvalidDisparity : 4.0f + (column * 7) % 5);
    scan.column_row.push_back(gap ? -1 : (column * 37) % 80);
  }
  std::vector<ColumnReading> readings;
  model.readings(scan, cam, readings);
  for (size_t i = 0; i < readings.size(); ++i) {
    EXPECT_LE(readings[i].left_slope, readings[i].right_slope) << "column " << readings[i].column;
    if (i > 0) {
      EXPECT_LE(readings[i - 1].right_slope, readings[i].left_slope);
    }
  }
  const GridFrame fine{-1.0, -3.0, 0.02};
  const mrpt::poses::CPose2D camera_pose(0.3, -0.2, mrpt::DEG2RAD(20.0));
  ScanRaster raster;
  model.rasterize(readings, camera_pose, fine, raster);
  std::map<std::pair<int, int>, int> hits;
  for (size_t i = 0; i < raster.spans.size(); ++i) {
    const CellSpan& s = raster.spans[i];
    for (int col = s.col_begin; col < s.col_end; ++col) ++hits[{col, s.row}];
  }
  for (const auto& [cell, count] : hits) EXPECT_EQ(count, 1) << cell.first << "," << cell.second;
  size_t occupied_cells = 0;
  for (size_t r = 0; r < readings.size(); ++r) {
    // raster.readings runs from image right to image left.
    const ReadingSpans& spans = raster.readings[readings.size() - 1 - r];
    const RegionCorners c = model.corners(readings[r], camera_pose);
    for (uint32_t i = spans.occupied_begin; i < spans.occupied_end; ++i) {
      const CellSpan& s = raster.spans[i];
      for (int col = s.col_begin; col < s.col_end; ++col) {
        ++occupied_cells;
        const double x = fine.origin_x + (col + 0.5) * fine.resolution;
        const double y = fine.origin_y + (s.row + 0.5) * fine.resolution;
        EXPECT_TRUE(insideConvex({c.near_right, c.far_right, c.far_left, c.near_left}, x, y))
            << "column " << readings[r].column << " cell " << col << "," << s.row;
      }
    }
  }
  EXPECT_GT(occupied_cells, 1000u);
}

TEST(StereoSensorModelTest, SubPixelUncertaintyNarrowsTheRegions) {
  // f = 100 px, fB = 10, d = 10, u = 0.25: depths 10/10.25 = 0.975610 and 10/9.75 = 1.025641.
  const DisparityScanCamera cam = camera(100.0, 50.0, 0.1);
  SensorModelOptions options;
  options.disparity_uncertainty_px = 0.25;
  const ColumnReading reading = StereoSensorModel(options).readingForDisparity(50, 10.0f, cam);
  EXPECT_NEAR(reading.near_depth_m, 0.9756097561, 1e-9);
  EXPECT_NEAR(reading.far_depth_m, 1.0256410256, 1e-9);
  // At d <= u the far edge goes to max_range_m.
  options.max_range_m = 30.0;
  EXPECT_DOUBLE_EQ(StereoSensorModel(options).readingForDisparity(50, 0.25f, cam).far_depth_m, 30.0);
}

TEST(StereoSensorModelTest, KeepObstacleBordersLeavesCellsTouchingOccAlone) {
  // The offset camera of the hand-geometry cases above, one column at d = 0.6 beside a nearer
  // one at d = 1.5, turned by 10 degrees, on a 0.25 m grid: the CLEAR cells must be the centre
  // rule's CLEAR cells less those with a corner inside one of the scan's OCC trapezoids
  // (checked here against the trapezoids' corners); the OCC cells do not change.
  const OffsetCase c;
  DisparityScan scan;
  scan.column_disparity = {0.6f, 1.5f};
  SensorModelOptions options;
  options.keep_obstacle_borders = true;
  const StereoSensorModel keeping(options);
  const StereoSensorModel centre{SensorModelOptions{}};
  const mrpt::poses::CPose2D robot(0.1, 0.5, mrpt::DEG2RAD(10.0));
  const GridFrame grid{-10.0, -10.0, 0.25};
  const RasterCells kept = rasterCells(keeping, c.cam, scan, robot, grid);
  const RasterCells all = rasterCells(centre, c.cam, scan, robot, grid);

  std::vector<ColumnReading> readings;
  keeping.readings(scan, c.cam, readings);
  const mrpt::poses::CPose2D camera_pose = robot + cameraFloorPose(c.cam.pose_on_robot);
  std::vector<std::vector<mrpt::math::TPoint2D>> trapezoids;
  for (const ColumnReading& reading : readings) {
    const RegionCorners r = keeping.corners(reading, camera_pose);
    trapezoids.push_back({r.near_right, r.far_right, r.far_left, r.near_left});
  }
  const auto touchesOcc = [&](const std::pair<int, int>& cell) {
    for (const double dx : {0.0, 1.0}) {
      for (const double dy : {0.0, 1.0}) {
        const double x = grid.origin_x + (cell.first + dx) * grid.resolution;
        const double y = grid.origin_y + (cell.second + dy) * grid.resolution;
        for (const auto& t : trapezoids) {
          if (insideConvex(t, x, y)) return true;
        }
      }
    }
    return false;
  };
  Cells expected;
  size_t left_alone = 0;
  for (const auto& cell : all.clear) {
    if (touchesOcc(cell)) {
      ++left_alone;
    } else {
      expected.insert(cell);
    }
  }
  EXPECT_EQ(kept.clear, expected);
  EXPECT_GE(left_alone, 3u);  // the near column's border and the far one's front row
  EXPECT_GE(expected.size(), 20u);
  EXPECT_EQ(kept.occupied, all.occupied);
}

}  // namespace
}  // namespace stereonav
