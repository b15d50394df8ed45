#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <vector>

#include "column_projection/disparity_scan.h"
#include "rig/camera_rig.h"
#include "sensor_model/polygon_rasterizer.h"
#include "sensor_model/sensor_model_options.h"

namespace stereonav {

// What the sensor model needs to know about the camera that produced a DisparityScan: the
// reference camera's focal length and principal point column, the unit baseline, and where the
// optical frame sits on the robot (CameraRig::pose_on_robot's convention).
struct DisparityScanCamera {
  double focal_px = 160.0;
  double cx = 159.5;
  double baseline_m = 0.10;
  mrpt::poses::CPose3D pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);

  static DisparityScanCamera fromRig(const CameraRig& rig);
  // Z = f B / d (paper section 3.2).
  double depthForDisparity(double disparity) const { return focal_px * baseline_m / disparity; }
};

// The camera on the floor plane: its (x, y) on the robot and the heading of its optical axis.
// Tilt and roll are dropped: the paper's 2D grid assumes a level head (section 3.3).
mrpt::poses::CPose2D cameraFloorPose(const mrpt::poses::CPose3D& optical_pose_on_robot);

// One column's reading reduced to depths along the optical axis (paper equation 1, figure 4):
// between the lines of sight through the column's two pixel edges, CLEAR is depth in
// [0, near_depth_m) and OCC is depth in [near_depth_m, far_depth_m) (empty when equal).
struct ColumnReading {
  int column = 0;
  float disparity = 0.0f;  // kInvalidDisparity for an invalid column cleared by option
  double near_depth_m = 0.0;
  double far_depth_m = 0.0;

  bool hasOccupiedRegion() const { return far_depth_m > near_depth_m; }
};

// The corners of a reading's regions; "left" is the image-left pixel edge x - 0.5, which is on
// the robot's left (+y) for a forward-looking camera. The CLEAR triangle is the camera centre
// and the two near corners.
struct RegionCorners {
  mrpt::math::TPoint2D near_left;
  mrpt::math::TPoint2D near_right;
  mrpt::math::TPoint2D far_left;
  mrpt::math::TPoint2D far_right;
};

// Where a grid's cells are: cell (i, j) covers [origin_x + i r, origin_x + (i+1) r) x
// [origin_y + j r, ...) with r = resolution, x right and y up (MRPT's COccupancyGridMap2D).
struct GridFrame {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double resolution = 0.05;
};

// Axis-aligned world bounds of a scan's regions, used to grow the grid before rasterising.
struct WorldBounds {
  double min_x;
  double max_x;
  double min_y;
  double max_y;
};

// One reading's OCC cells: spans [occupied_begin, occupied_end) of ScanRaster::spans.
struct ReadingSpans {
  float disparity;
  uint32_t occupied_begin;
  uint32_t occupied_end;
};

// A whole scan rasterised. The CLEAR regions of all readings tile one star-shaped area around
// the camera, so they are rasterised together as one polygon (far fewer rows than triangle by
// triangle) into spans [clear_begin, spans.size()); each cell appears at most once per scan.
// Reused from scan to scan so that its buffers keep their capacity.
struct ScanRaster {
  std::vector<ReadingSpans> readings;
  CellSpanBuffer spans;
  size_t clear_begin = 0;
  std::vector<ScanEdge> clear_edges;  // scratch
};

// The stereo sensor model of paper section 3.2: each column's disparity becomes a trapezoid
// region of uncertainty (OCC) and a clear triangle (CLEAR) on the floor, rasterised exactly into
// grid cells (a cell belongs to a region when its centre does; see appendCellSpans). Adjacent
// columns share their boundary rays, so one scan's regions never overlap: every cell gets at
// most one update per scan, and the CLEAR triangles can be filled as their union.
class StereoSensorModel {
 public:
  explicit StereoSensorModel(const SensorModelOptions& options) : options_(options) {}

  const SensorModelOptions& options() const { return options_; }

  // The readings of a scan: one per column with a valid disparity (d >= 0), plus, when
  // clear_invalid_columns_to_m > 0, a CLEAR-only reading per invalid column. Reuses `readings`.
  void readings(const DisparityScan& scan, const DisparityScanCamera& camera,
                std::vector<ColumnReading>& readings) const;
  ColumnReading readingForDisparity(int column, float disparity,
                                    const DisparityScanCamera& camera) const;

  // Corners in the frame where `camera_floor_pose` is given: the camera's own floor frame (x
  // along the optical axis, y left) for the identity, the world for robot pose + camera pose.
  RegionCorners corners(const ColumnReading& reading, const DisparityScanCamera& camera,
                        const mrpt::poses::CPose2D& camera_floor_pose) const;

  WorldBounds bounds(const std::vector<ColumnReading>& readings,
                     const DisparityScanCamera& camera,
                     const mrpt::poses::CPose2D& camera_floor_pose) const;

  // Rasterises every reading's CLEAR and OCC regions into `raster` (cleared first).
  void rasterize(const std::vector<ColumnReading>& readings, const DisparityScanCamera& camera,
                 const mrpt::poses::CPose2D& camera_floor_pose, const GridFrame& frame,
                 ScanRaster& raster) const;

 private:
  SensorModelOptions options_;
};

}  // namespace stereonav
