#include "mapping/stereo_mapper.h"

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "column_projection/virtual_range_scan.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::SyntheticScene;
using testing::Wall;

constexpr double kWallX = 2.0;

// A textured wall across the robot's view, kWallX metres ahead of the robot's start.
SyntheticScene wallAhead() { return SyntheticScene({Wall{kWallX, -3.0, kWallX, 3.0}}); }

// Occupancy G of the paper's grid, or 255 (1 - p_free) of MRPT's, at world point (x, y).
double occupancyAt(const mrpt::maps::CMetricMap& map, double x, double y) {
  if (const auto* stereo = dynamic_cast<const CStereoOccupancyGridMap*>(&map)) {
    int col, row;
    EXPECT_TRUE(stereo->grid().cellAt(x, y, col, row));
    return stereo->grid().occupancy(col, row);
  }
  const auto& grid = dynamic_cast<const mrpt::maps::COccupancyGridMap2D&>(map);
  return 255.0 * (1.0 - grid.getPos(static_cast<float>(x), static_cast<float>(y)));
}

// Most occupied value on the segment x in [x0, x1] at height y (the wall's cells, whatever the
// quantisation of the disparity puts them at within one grid cell either side).
double maxOccupancyAlong(const mrpt::maps::CMetricMap& map, double x0, double x1, double y) {
  double highest = 0.0;
  for (double x = x0; x <= x1; x += 0.01) highest = std::max(highest, occupancyAt(map, x, y));
  return highest;
}

// `farthest_camera_x`: where the camera got closest to the wall; every point checked for free
// space is seen from there within 30 degrees of the optical axis, well inside the 45 degree
// half field of view.
void expectWallMapped(const mrpt::maps::CMetricMap& map, double wall_x, double farthest_camera_x = 0.0) {
  for (const double y : {-0.6, -0.3, 0.0, 0.3, 0.6}) {
    SCOPED_TRACE("y = " + std::to_string(y));
    // Occupied (G > 150, the paper's "definitely obstructed") within a cell of the wall.
    EXPECT_GT(maxOccupancyAlong(map, wall_x - 0.1, wall_x + 0.1, y), 150.0);
    // Free (G < 50) between the robot and the wall.
    const double first_x = std::max(0.7, farthest_camera_x + std::abs(y) / std::tan(M_PI / 6));
    for (double x = first_x; x <= wall_x - 0.4; x += 0.1) EXPECT_LT(occupancyAt(map, x, y), 50.0) << x;
    // Nothing seen behind the wall: unknown.
    EXPECT_NEAR(occupancyAt(map, wall_x + 1.0, y), 128.0, 1.0);
  }
  // Nor anywhere behind the robot.
  EXPECT_NEAR(occupancyAt(map, -1.0, 0.0), 128.0, 1.0);
}

MappingOptions optionsFor(GridModel model) {
  MappingOptions options;
  options.grid.model = model;
  return options;
}

TEST(StereoMapperTest, LinearGridMapsAWallAheadOccupiedAndTheFloorBeforeItFree) {
  const SyntheticScene scene = wallAhead();
  StereoMapper mapper(optionsFor(GridModel::kLinear), testing::testRig());
  // Six readings from a standing robot: six K = 20 steps take G from 128 past both thresholds.
  for (int i = 0; i < 6; ++i) {
    mapper.process(scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(i)), {});
  }
  EXPECT_EQ(mapper.framesMapped(), 6u);
  expectWallMapped(mapper.map(), kWallX);
}

TEST(StereoMapperTest, DrivingTowardsTheWallKeepsItWhereItIs) {
  const SyntheticScene scene = wallAhead();
  StereoMapper mapper(optionsFor(GridModel::kLinear), testing::testRig());
  for (int i = 0; i < 8; ++i) {
    const mrpt::poses::CPose2D pose(0.05 * i, 0.0, 0.0);
    mapper.process(scene.renderFrame(testing::testRig(), pose, mrpt::Clock::fromDouble(i)), pose);
  }
  expectWallMapped(mapper.map(), kWallX, 0.35);
}

TEST(StereoMapperTest, AWallNearerThanTheDisparityRangeClearsNothingBehindItsFace) {
  // f B = 16 px m: a wall 0.4 m ahead has disparity 40, beyond the matcher's range of 0-31
  // (nearest depth 16 / 31 = 0.52 m). Matched, it reads at the range's top, as if 0.52 m away,
  // and its CLEAR would run up to 16 / 31.5 = 0.51 m, through the wall's face. The frames are
  // identical renders, so a cell whose centre lies in a column's wedge is updated by that
  // column's reading alone, six times.
  constexpr double kNearWallX = 0.4;
  const SyntheticScene scene({Wall{kNearWallX, -3.0, kNearWallX, 3.0}});
  const CameraRig rig = testing::testRig();
  StereoMapper mapper(optionsFor(GridModel::kLinear), rig);
  for (int i = 0; i < 6; ++i) mapper.process(scene.renderFrame(rig, {}, mrpt::Clock::fromDouble(i)), {});
  const DisparityScan& scan = mapper.scanner().lastScan();
  const auto& stereo = dynamic_cast<const CStereoOccupancyGridMap&>(mapper.map());
  const DisparityTaggedGrid& grid = stereo.grid();
  int checked = 0;
  for (double y = -0.35; y <= 0.35; y += 0.05) {
    int col = 0, row = 0;
    ASSERT_TRUE(grid.cellAt(kNearWallX + 0.05, y, col, row));
    // The cell centre behind the face, and the image column whose wedge holds it (the camera is
    // at the robot's centre, looking along +x; image right is -y).
    const double centre_x = grid.minX() + (col + 0.5) * grid.resolution();
    const double centre_y = grid.minY() + (row + 0.5) * grid.resolution();
    // Between the face and the reach of a range-top CLEAR.
    if (centre_x <= kNearWallX || centre_x >= 16.0 / 31.5) continue;
    const int column = static_cast<int>(std::lround(rig.reference.cx - rig.reference.focal_px * centre_y / centre_x));
    if (column < 0 || column >= scan.columns() || !scan.atRangeTop(column)) continue;
    ++checked;
    EXPECT_GE(grid.occupancy(col, row), 128) << "cell centred at (" << centre_x << ", " << centre_y << ")";
  }
  EXPECT_GE(checked, 3) << "cells behind the face seen through columns read at the range's top";
}

TEST(StereoMapperTest, TurnedRobotMapsTheWallInTheWorldFrame) {
  // The wall now runs along y = 2 and the robot looks along +y: the map must rotate the scan.
  const SyntheticScene scene({Wall{-3.0, 2.0, 3.0, 2.0}});
  StereoMapper mapper(optionsFor(GridModel::kLinear), testing::testRig());
  const mrpt::poses::CPose2D pose(0.0, 0.0, M_PI / 2);
  for (int i = 0; i < 6; ++i) {
    mapper.process(scene.renderFrame(testing::testRig(), pose, mrpt::Clock::fromDouble(i)), pose);
  }
  EXPECT_GT(std::max({occupancyAt(mapper.map(), 0.0, 1.95), occupancyAt(mapper.map(), 0.0, 2.0),
                      occupancyAt(mapper.map(), 0.0, 2.05)}),
            150.0);
  EXPECT_LT(occupancyAt(mapper.map(), 0.0, 1.0), 50.0);
  EXPECT_NEAR(occupancyAt(mapper.map(), 1.0, 0.0), 128.0, 1.0);  // where it did not look
}

TEST(StereoMapperTest, MrptBayesGridMapsTheSameWallThroughTheVirtualScan) {
  const SyntheticScene scene = wallAhead();
  StereoMapper mapper(optionsFor(GridModel::kMrptBayes), testing::testRig());
  for (int i = 0; i < 6; ++i) {
    mapper.process(scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(i)), {});
  }
  ASSERT_NE(mapper.virtualScan(), nullptr);
  // The straight-ahead ray of the virtual laser measures the wall's distance from the camera.
  const auto& scan = *mapper.virtualScan();
  const size_t middle = scan.getScanSize() / 2;
  ASSERT_TRUE(scan.getScanRangeValidity(middle));
  EXPECT_NEAR(scan.getScanRange(middle), kWallX, 0.15);
  expectWallMapped(mapper.map(), kWallX);
}

// Mean signed error (measured - true) of a virtual scan's rays within 20 degrees of straight
// ahead, against the wall kWallX ahead of a camera at the robot's origin.
double meanRangeErrorOnTheWallAhead(const mrpt::obs::CObservation2DRangeScan& scan) {
  double sum = 0.0;
  int rays = 0;
  for (size_t i = 0; i < scan.getScanSize(); ++i) {
    const double bearing = -0.5 * scan.aperture + scan.aperture * i / (scan.getScanSize() - 1);
    if (std::abs(bearing) > M_PI / 9 || !scan.getScanRangeValidity(i)) continue;
    sum += scan.getScanRange(i) - kWallX / std::cos(bearing);
    ++rays;
  }
  EXPECT_GT(rays, 10);
  return sum / rays;
}

TEST(StereoMapperTest, TheVirtualScanReadsTheSurfaceWhereTheMapKeepsItsNearestPoint) {
  const SyntheticScene scene = wallAhead();
  MappingOptions options = optionsFor(GridModel::kLinear);
  options.mapper.virtual_scans = true;
  options.projection.surface_band_px = 2.0;
  options.projection.surface_band_scan_only = true;
  options.stereo.subpixel = true;
  StereoMapper mapper(options, testing::testRig());
  // Sensor noise (sigma 3 grey levels, fixed seed) spreads each column's disparities as a real
  // camera's does; the rendered images alone match exactly.
  RigFrame frame = scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(0));
  cv::RNG noise(7);
  for (cv::Mat* image : {&frame.reference, &frame.secondaries[0], &frame.secondaries[1]}) {
    cv::Mat grain(image->size(), CV_16SC(image->channels()));
    noise.fill(grain, cv::RNG::NORMAL, 0.0, 3.0);
    cv::add(*image, grain, *image, cv::noArray(), image->type());
  }
  mapper.process(frame, {});
  // The paper's reading, the largest of each column's noisy disparities, reads the wall too near
  // (2.8 cm here); the surface's median reads it where it is (0.04 mm).
  const double nearest_error = meanRangeErrorOnTheWallAhead(makeVirtualRangeScan(
      mapper.disparityScan().scan, testing::testRig(), options.projection.scan_max_range_m));
  const double surface_error = meanRangeErrorOnTheWallAhead(*mapper.virtualScan());
  EXPECT_LT(nearest_error, -0.01);
  EXPECT_LT(std::abs(surface_error), 0.5 * std::abs(nearest_error));
}

TEST(StereoMapperTest, RecordsTimeForEveryStageAndCountsMatchedPixels) {
  const SyntheticScene scene = wallAhead();
  MappingOptions options = optionsFor(GridModel::kLinear);
  options.mapper.virtual_scans = true;
  StereoMapper mapper(options, testing::testRig());
  mapper.process(scene.renderFrame(testing::testRig(), {}, mrpt::Clock::fromDouble(0)), {});
  for (const auto stage : {PipelineStage::kStereo, PipelineStage::kSpikeRemoval,
                           PipelineStage::kProjection, PipelineStage::kVirtualScan,
                           PipelineStage::kGridUpdate}) {
    EXPECT_GT(mapper.times().totalMs(stage), 0.0) << stageName(stage);
  }
  // The wall fills the image between the floor and its top edge; floor and sky are flat and
  // must not match, so matched pixels lie between the wall's rows.
  const auto& scanner = mapper.scanner();
  const CameraRig rig = testing::testRig();
  // Rows of the wall at 2 m: heights 0..2 m from a camera 0.5 m up, y = cy - f (z - 0.5) / 2.
  const double top_row = rig.reference.cy - rig.reference.focal_px * 1.5 / kWallX;
  const double bottom_row = rig.reference.cy + rig.reference.focal_px * 0.5 / kWallX;
  const double wall_fraction = (bottom_row - top_row) / rig.reference.height;
  EXPECT_GT(scanner.keptPixels(), 0u);
  EXPECT_LE(scanner.keptPixels(), scanner.matchedPixels());
  EXPECT_LE(static_cast<double>(scanner.matchedPixels()) / scanner.disparity().total(),
            wall_fraction + 0.02);
  EXPECT_GT(static_cast<double>(scanner.keptPixels()) / scanner.disparity().total(),
            0.5 * wall_fraction);
}

TEST(StereoMapperTest, RefusesAFrameOfAnotherSize) {
  const SyntheticScene scene = wallAhead();
  StereoMapper mapper(optionsFor(GridModel::kLinear), testing::testRig());
  CameraRig small = testing::testRig();
  small.reference.width = 160;
  small.reference.height = 120;
  EXPECT_THROW(mapper.process(scene.renderFrame(small, {}, mrpt::Clock::fromDouble(0)), {}),
               std::invalid_argument);
}

}  // namespace
}  // namespace stereonav
