// Inserting one realistic disparity scan into the paper's grid (CStereoOccupancyGridMap) versus
// inserting the equivalent virtual laser scan into MRPT's COccupancyGridMap2D, same resolution,
// same run, repetitions interleaved so that both meet the same disturbances:
//   bench_occupancy_grid --benchmark_repetitions=15 --benchmark_enable_random_interleaving=true
//                        --benchmark_report_aggregates_only=true
// Compare the _min rows: on a shared virtual machine the medians of a few microseconds scatter by
// +-20% from run to run, the fastest repetition by about 1%.
#include <benchmark/benchmark.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "occupancy_grid/stereo_occupancy_grid_map.h"

namespace stereonav {
namespace {

constexpr double kResolution = 0.05;

double fastest(const std::vector<double>& times) { return *std::min_element(times.begin(), times.end()); }

// A 320x240 Triclops-like head (f = 160 px: 90 deg field of view, B = 0.1 m) at the origin,
// looking along +x into a 9 x 6 m room (walls x = -1, x = 8, y = -3, y = 3) with a box at 1-1.6 m
// and a pillar at 4 m: column depths from 1 to 8 m. Disparities are whole pixels, as in the paper
// (no sub-pixel interpolation).
struct Scene {
  DisparityScanCamera camera;
  CObservationDisparityScan observation;
  mrpt::obs::CObservation2DRangeScan laser;
};

// Distance along (dx, dy) from the origin to the nearest of the room's surfaces.
double hitDistance(double dx, double dy) {
  double best = std::numeric_limits<double>::infinity();
  const auto wall_x = [&](double x) {
    const double t = x / dx;
    if (t > 0 && std::abs(t * dy) <= 3.0) best = std::min(best, t);
  };
  const auto wall_y = [&](double y) {
    const double t = y / dy;
    if (t > 0 && t * dx >= -1.0 && t * dx <= 8.0) best = std::min(best, t);
  };
  const auto box = [&](double x0, double x1, double y0, double y1) {
    for (const double x : {x0, x1}) {
      const double t = x / dx;
      if (t > 0 && t * dy >= y0 && t * dy <= y1) best = std::min(best, t);
    }
    for (const double y : {y0, y1}) {
      const double t = y / dy;
      if (t > 0 && t * dx >= x0 && t * dx <= x1) best = std::min(best, t);
    }
  };
  wall_x(8.0);
  wall_x(-1.0);
  wall_y(3.0);
  wall_y(-3.0);
  box(1.0, 1.6, 0.3, 0.9);
  box(4.0, 4.3, -1.5, -1.2);
  return best;
}

Scene makeScene() {
  Scene scene;
  CameraRig rig;
  rig.reference = {320, 240, 160.0, 159.5, 119.5};
  rig.baseline_m = 0.1;
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  scene.camera = DisparityScanCamera::fromRig(rig);
  const double f = rig.reference.focal_px, cx = rig.reference.cx;

  DisparityScan& scan = scene.observation.scan;
  scan.column_disparity.resize(rig.reference.width);
  for (int column = 0; column < rig.reference.width; ++column) {
    const double left = -(column - cx) / f;  // lateral per metre of depth, robot-left positive
    const double t = hitDistance(1.0, left);  // along (1, left): t is the depth Z
    scan.column_disparity[column] = static_cast<float>(std::round(rig.disparityForDepth(t)));
  }
  scene.observation.camera = scene.camera;

  // The equivalent virtual laser: one ray per column, evenly spaced over the 90 deg aperture,
  // counter-clockwise; each ray takes the range of the column nearest its bearing, from that
  // column's (whole-pixel) disparity.
  mrpt::obs::CObservation2DRangeScan& laser = scene.laser;
  const double half_aperture = std::atan((cx + 0.5) / f);
  laser.aperture = static_cast<float>(2 * half_aperture);
  laser.rightToLeft = true;
  laser.maxRange = 15.0f;
  laser.sensorPose = mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0);
  const size_t rays = scan.column_disparity.size();
  laser.resizeScanAndAssign(rays, laser.maxRange, false);
  for (size_t ray = 0; ray < rays; ++ray) {
    const double bearing = -half_aperture + 2 * half_aperture * ray / (rays - 1);
    // The outermost rays point at the image's outer pixel edges (column -0.5 and width - 0.5):
    // they take the edge columns' readings.
    const int last_column = rig.reference.width - 1;
    const int column = std::clamp(static_cast<int>(std::lround(cx - f * std::tan(bearing))), 0, last_column);
    const double depth = rig.depthForDisparity(scan.column_disparity[column]);
    laser.setScanRange(ray, static_cast<float>(depth / std::cos(bearing)));
    laser.setScanRangeValidity(ray, true);
  }
  return scene;
}

void BM_StereoOccupancyGridInsertDisparityScan(benchmark::State& state) {
  const Scene scene = makeScene();
  StereoGridMapOptions options;
  options.limits.resolution = kResolution;
  options.update.accuracy_preservation = state.range(0) != 0;
  options.update.free_preservation_range_m = static_cast<double>(state.range(1));
  CStereoOccupancyGridMap map(options);
  const mrpt::poses::CPose3D robot;
  for (auto _ : state) {
    map.insertObservation(scene.observation, robot);
    benchmark::ClobberMemory();
  }
  state.counters["cells"] = map.grid().width() * map.grid().height();
}
BENCHMARK(BM_StereoOccupancyGridInsertDisparityScan)
    ->ArgNames({"accuracy_preservation", "free_preservation_range_m"})
    ->Args({1, 0})
    ->Args({0, 0})
    ->Args({1, 2})
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);

void BM_MrptOccupancyGridInsertRangeScan(benchmark::State& state) {
  const Scene scene = makeScene();
  mrpt::maps::COccupancyGridMap2D map(-10, 10, -10, 10, kResolution);
  const mrpt::poses::CPose3D robot;
  for (auto _ : state) {
    map.insertObservation(scene.laser, robot);
    benchmark::ClobberMemory();
  }
  state.counters["cells"] = map.getSizeX() * map.getSizeY();
}
BENCHMARK(BM_MrptOccupancyGridInsertRangeScan)->ComputeStatistics("min", fastest)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
