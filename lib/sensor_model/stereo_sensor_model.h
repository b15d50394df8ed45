#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "column_projection/disparity_scan.h"
#include "occupancy_grid/grid_frame.h"
#include "rig/camera_rig.h"
#include "sensor_model/polygon_rasterizer.h"
#include "sensor_model/sensor_model_options.h"

namespace stereonav {

// What the sensor model needs to know about the camera that produced a DisparityScan: the
// reference camera's focal length and principal point, the unit baseline, and where the optical
// frame sits on the robot (CameraRig::pose_on_robot's convention).
struct DisparityScanCamera {
  double focal_px = 160.0;
  double cx = 159.5;
  double cy = 119.5;
  double baseline_m = 0.10;
  mrpt::poses::CPose3D pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);

  static DisparityScanCamera fromRig(const CameraRig& rig);
  // Z = f B / d (paper section 3.2).
  double depthForDisparity(double disparity) const { return focal_px * baseline_m / disparity; }
};

// The head's tilt below the horizon, t, from the optical frame's pose on the robot (roll is not
// modelled).
struct HeadTilt {
  double cos_tilt;
  double sin_tilt;
  static HeadTilt of(const mrpt::poses::CPose3D& optical_pose_on_robot);
};

// The camera on the floor plane: the point below its optical centre and the heading of its
// optical axis. The regions of a reading are laid out in this frame; the head's tilt enters
// through the row each reading was seen in (ColumnReading::floor_per_depth, edge slopes).
mrpt::poses::CPose2D cameraFloorPose(const mrpt::poses::CPose3D& optical_pose_on_robot);

// One column's reading (paper equation 1, figure 4): depths Z(d + u) and Z(d - u) along the
// optical axis (u = SensorModelOptions::disparity_uncertainty_px, 0.5 in the paper), and where
// they fall on the floor. The pixel at image row y and depth Z lies
// Z (cos t - v sin t) ahead of the camera's floor point (along its heading) for a head tilted
// down by t, v = (y - cy) / f, and Z (x - cx) / f to the image right: so between the lines of
// sight through the column's two pixel edges, CLEAR is forward distance [0, near) and OCC is
// [near, far) (empty when equal), near and far = depth times floor_per_depth. A level head has
// floor_per_depth 1 and slopes (x -/+ 0.5 - cx) / f: depth is floor distance, as the paper
// draws it. Head roll is not modelled (image rows are taken as level).
struct ColumnReading {
  int column = 0;
  float disparity = 0.0f;  // kInvalidDisparity for an invalid column cleared by option
  double near_depth_m = 0.0;
  double far_depth_m = 0.0;
  // Forward distance on the floor per metre of depth, cos t - v sin t, for the reading's row.
  double floor_per_depth = 1.0;
  // The column's lines of sight on the floor through its image-left (x - 0.5) and image-right
  // (x + 0.5) pixel edges, in metres to the image right per metre forward: (edge - cx) / f /
  // floor_per_depth for the reading alone; readings() makes neighbours share them.
  double left_slope = 0.0;
  double right_slope = 0.0;

  // CLEAR ends here (forward distance) when it is nearer than the OCC region
  // (DisparityScan::column_clear_end).
  double clear_end_m = std::numeric_limits<double>::infinity();

  double nearDistance() const { return near_depth_m * floor_per_depth; }
  double clearDistance() const { return std::min(nearDistance(), clear_end_m); }
  double farDistance() const { return far_depth_m * floor_per_depth; }
  bool hasOccupiedRegion() const { return far_depth_m > near_depth_m && right_slope > left_slope; }
};

// The corners of a reading's regions; "left" is the image-left pixel edge x - 0.5, which is on
// the robot's left (+y) for a forward-looking camera. The CLEAR triangle is the camera's floor
// point and the two near corners.
struct RegionCorners {
  mrpt::math::TPoint2D near_left;
  mrpt::math::TPoint2D near_right;
  mrpt::math::TPoint2D far_left;
  mrpt::math::TPoint2D far_right;
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
  // Scratch: the CLEAR outline and its scan conversion's buffers; for
  // SensorModelOptions::keep_obstacle_borders also the cell corners inside OCC regions, the
  // cells they touch, and the cells the outline covers.
  std::vector<ScanEdge> clear_edges;
  PolygonScanScratch clear_scan;
  CellSpanBuffer occupied_corners;
  std::vector<CellSpan> border_cells;
  CellSpanBuffer clear_cells;
};

// The stereo sensor model of paper section 3.2: each column's disparity becomes a trapezoid
// region of uncertainty (OCC) and a clear triangle (CLEAR) on the floor, rasterised exactly into
// grid cells (a cell belongs to a region when its centre does; see appendCellSpans). Adjacent
// columns share their boundary rays, so one scan's regions never overlap: every cell gets at
// most one update per scan, and the CLEAR triangles can be filled as their union.
//
// A tilted head sees each column's reading in some image row, and where a pixel edge's line of
// sight meets the floor plane depends on that row (a tilted image column is not a vertical
// plane). Two adjacent columns read in different rows would bound their shared edge by two
// different rays, overlapping or leaving a sliver. readings() therefore gives each shared edge
// ONE ray, that of the nearer of the two readings (its obstacle is where the edge really is; the
// farther column is seen beside it), and then keeps all rays in image order, across gaps too:
// where two edges are out of order, the one belonging to the farther reading takes the nearer
// one's ray. A farther column whose own wedge lies wholly on the wrong side of a nearer
// neighbour's ray is left with an empty wedge for that scan (on the office run about one reading
// in seven, at row jumps between columns). So the shared-EdgeLine convention of the rasteriser
// still holds and every cell gets at most one update per scan. A level head has the same ray on
// both sides of every edge, in order, and none of this changes anything.
class StereoSensorModel {
 public:
  explicit StereoSensorModel(const SensorModelOptions& options) : options_(options) {}

  const SensorModelOptions& options() const { return options_; }

  // The readings of a scan: one per column with a valid disparity (d >= 0) below the matcher's
  // range top (DisparityScan::atRangeTop: a bound, not a depth), plus, when
  // clear_invalid_columns_to_m > 0, a CLEAR-only reading per invalid column; with the shared
  // edge rays described above. A column without a row (scan.column_row empty or -1, e.g. a scan
  // not made by ColumnProjector) and a CLEAR-only reading count as seen in the optical axis' row
  // cy. A column whose scan ends its CLEAR (DisparityScan::endsClear) gets clear_end_m there.
  // Reuses `readings`.
  void readings(const DisparityScan& scan, const DisparityScanCamera& camera,
                std::vector<ColumnReading>& readings) const;
  // One reading on its own (its own row's rays), seen in image row `row` (the optical axis' row
  // cy when not given).
  ColumnReading readingForDisparity(int column, float disparity, const DisparityScanCamera& camera,
                                    std::optional<int> row = std::nullopt) const;

  // Corners in the frame where `camera_floor_pose` is given: the camera's own floor frame (x
  // along its heading, y left) for the identity, the world for robot pose + camera pose.
  RegionCorners corners(const ColumnReading& reading,
                        const mrpt::poses::CPose2D& camera_floor_pose) const;

  WorldBounds bounds(const std::vector<ColumnReading>& readings,
                     const mrpt::poses::CPose2D& camera_floor_pose) const;

  // Rasterises every reading's CLEAR and OCC regions into `raster` (cleared first), keeping
  // only the cells inside `window` (a grid's cells: CellWindow::grid).
  void rasterize(const std::vector<ColumnReading>& readings,
                 const mrpt::poses::CPose2D& camera_floor_pose, const GridFrame& frame,
                 ScanRaster& raster, const CellWindow& window = CellWindow::all()) const;

 private:
  // An edge between readings while readings() shares them out: its slope and the reading the
  // slope belongs to (near distance, then column: which of two conflicting edges yields).
  struct EdgeRay {
    double slope;
    double owner_near_m;
    int owner_column;
    bool nearerThan(const EdgeRay& other) const {
      return owner_near_m < other.owner_near_m ||
             (owner_near_m == other.owner_near_m && owner_column < other.owner_column);
    }
  };
  ColumnReading reading(int column, float disparity, const DisparityScanCamera& camera,
                        const HeadTilt& tilt, double row) const;
  void shareEdgeRays(std::vector<ColumnReading>& readings) const;

  SensorModelOptions options_;
  mutable std::vector<EdgeRay> edge_rays_;  // scratch: a model is not shared between threads
};

}  // namespace stereonav
