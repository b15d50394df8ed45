#include "sensor_model/stereo_sensor_model.h"

#include <mrpt/math/CMatrixFixed.h>

#include <algorithm>
#include <cmath>

namespace stereonav {

namespace {

// The camera's floor frame expressed in some target frame (world or cell units): its centre,
// the optical axis and the image-right direction, per metre of depth.
struct FloorAxes {
  CellPoint centre;
  CellPoint forward;
  CellPoint image_right;
};

FloorAxes floorAxes(const mrpt::poses::CPose2D& pose, const GridFrame& frame) {
  const double scale = 1.0 / frame.resolution;
  const double c = std::cos(pose.phi()) * scale;
  const double s = std::sin(pose.phi()) * scale;
  return {{(pose.x() - frame.origin_x) * scale, (pose.y() - frame.origin_y) * scale},
          {c, s},
          {s, -c}};
}

// The line of sight through image column boundary `edge_x` (a pixel edge, x +/- 0.5): per metre
// of depth Z it moves (edge_x - cx) / f metres to the image right (paper section 3.2).
CellPoint lineOfSight(const FloorAxes& axes, const DisparityScanCamera& camera, double edge_x) {
  const double lateral = (edge_x - camera.cx) / camera.focal_px;
  return {axes.forward.u + lateral * axes.image_right.u,
          axes.forward.v + lateral * axes.image_right.v};
}

CellPoint pointAtDepth(const FloorAxes& axes, const CellPoint& line_of_sight, double depth) {
  return {axes.centre.u + depth * line_of_sight.u, axes.centre.v + depth * line_of_sight.v};
}

EdgeLine rayLine(const FloorAxes& axes, const CellPoint& line_of_sight) {
  return {axes.centre.u, axes.centre.v, line_of_sight.u / line_of_sight.v};
}

mrpt::math::TPoint2D toPoint(const CellPoint& p) { return {p.u, p.v}; }

const GridFrame kMetricFrame{0.0, 0.0, 1.0};

RegionCorners cornersOf(const ColumnReading& reading, const DisparityScanCamera& camera,
                        const FloorAxes& axes) {
  const CellPoint left = lineOfSight(axes, camera, reading.column - 0.5);
  const CellPoint right = lineOfSight(axes, camera, reading.column + 0.5);
  return {toPoint(pointAtDepth(axes, left, reading.near_depth_m)),
          toPoint(pointAtDepth(axes, right, reading.near_depth_m)),
          toPoint(pointAtDepth(axes, left, reading.far_depth_m)),
          toPoint(pointAtDepth(axes, right, reading.far_depth_m))};
}

}  // namespace

DisparityScanCamera DisparityScanCamera::fromRig(const CameraRig& rig) {
  DisparityScanCamera camera;
  camera.focal_px = rig.reference.focal_px;
  camera.cx = rig.reference.cx;
  camera.baseline_m = rig.baseline_m;
  camera.pose_on_robot = rig.pose_on_robot;
  return camera;
}

mrpt::poses::CPose2D cameraFloorPose(const mrpt::poses::CPose3D& optical_pose_on_robot) {
  const auto rotation = optical_pose_on_robot.getRotationMatrix();
  // Column 2 of the rotation is the optical (z) axis in the robot frame.
  return {optical_pose_on_robot.x(), optical_pose_on_robot.y(),
          std::atan2(rotation(1, 2), rotation(0, 2))};
}

ColumnReading StereoSensorModel::readingForDisparity(int column, float disparity,
                                                     const DisparityScanCamera& camera) const {
  ColumnReading reading;
  reading.column = column;
  reading.disparity = disparity;
  reading.near_depth_m = camera.depthForDisparity(disparity + 0.5);
  // Equation 1 with d - 0.5 <= 0 puts the obstacle out to infinity.
  reading.far_depth_m = disparity > 0.5f ? camera.depthForDisparity(disparity - 0.5)
                                         : options_.max_range_m;
  reading.far_depth_m = std::max(reading.far_depth_m, reading.near_depth_m);
  return reading;
}

void StereoSensorModel::readings(const DisparityScan& scan, const DisparityScanCamera& camera,
                                 std::vector<ColumnReading>& readings) const {
  readings.clear();
  for (int column = 0; column < scan.columns(); ++column) {
    const float disparity = scan.column_disparity[column];
    if (isValidDisparity(disparity) && disparity >= 0.0f) {
      readings.push_back(readingForDisparity(column, disparity, camera));
    } else if (options_.clear_invalid_columns_to_m > 0.0) {
      const double depth = options_.clear_invalid_columns_to_m;
      readings.push_back({column, kInvalidDisparity, depth, depth});
    }
  }
}

RegionCorners StereoSensorModel::corners(const ColumnReading& reading,
                                         const DisparityScanCamera& camera,
                                         const mrpt::poses::CPose2D& camera_floor_pose) const {
  return cornersOf(reading, camera, floorAxes(camera_floor_pose, kMetricFrame));
}

WorldBounds StereoSensorModel::bounds(const std::vector<ColumnReading>& readings,
                                      const DisparityScanCamera& camera,
                                      const mrpt::poses::CPose2D& camera_floor_pose) const {
  WorldBounds bounds{camera_floor_pose.x(), camera_floor_pose.x(), camera_floor_pose.y(),
                     camera_floor_pose.y()};
  const auto include = [&](const CellPoint& p) {
    bounds.min_x = std::min(bounds.min_x, p.u);
    bounds.max_x = std::max(bounds.max_x, p.u);
    bounds.min_y = std::min(bounds.min_y, p.v);
    bounds.max_y = std::max(bounds.max_y, p.v);
  };
  // Every region lies in the triangle camera - far corners (CLEAR-only readings have their far
  // depth at their near depth), so the far corners bound them all.
  const FloorAxes axes = floorAxes(camera_floor_pose, kMetricFrame);
  for (const ColumnReading& reading : readings) {
    include(pointAtDepth(axes, lineOfSight(axes, camera, reading.column - 0.5), reading.far_depth_m));
    include(pointAtDepth(axes, lineOfSight(axes, camera, reading.column + 0.5), reading.far_depth_m));
  }
  return bounds;
}

void StereoSensorModel::rasterize(const std::vector<ColumnReading>& readings,
                                  const DisparityScanCamera& camera,
                                  const mrpt::poses::CPose2D& camera_floor_pose,
                                  const GridFrame& frame, ScanRaster& raster) const {
  raster.readings.clear();
  raster.spans.clear();
  raster.clear_edges.clear();
  const FloorAxes axes = floorAxes(camera_floor_pose, frame);
  std::vector<ScanEdge>& clear = raster.clear_edges;
  // Walk the columns from image right to image left: counter-clockwise around the camera. The
  // CLEAR union's outline runs camera -> near right -> near left -> (along the shared line of
  // sight) the next column's near right ... -> camera, returning to the camera at every gap.
  const ColumnReading* previous = nullptr;
  CellPoint previous_near_left{};
  CellPoint previous_left{};
  EdgeLine previous_left_ray{};
  for (auto it = readings.rbegin(); it != readings.rend(); ++it) {
    const ColumnReading& reading = *it;
    // Neighbouring columns share the line of sight through their common pixel edge: the one
    // to the right hands its left line over (the same numbers it would compute, since
    // x + 0.5 == (x + 1) - 0.5 exactly), so both sides of the edge use one EdgeLine.
    const bool adjacent = previous != nullptr && previous->column == reading.column + 1;
    const CellPoint right = adjacent ? previous_left : lineOfSight(axes, camera, reading.column + 0.5);
    const EdgeLine right_ray = adjacent ? previous_left_ray : rayLine(axes, right);
    const CellPoint left = lineOfSight(axes, camera, reading.column - 0.5);
    const EdgeLine left_ray = rayLine(axes, left);
    const CellPoint near_left = pointAtDepth(axes, left, reading.near_depth_m);
    const CellPoint near_right = pointAtDepth(axes, right, reading.near_depth_m);
    const EdgeLine near_edge = EdgeLine::through(near_left, near_right);

    if (adjacent) {
      ScanEdge::appendTo(clear, previous_near_left, near_right, right_ray);
    } else {
      if (previous != nullptr) {
        ScanEdge::appendTo(clear, previous_near_left, axes.centre, previous_left_ray);
      }
      ScanEdge::appendTo(clear, axes.centre, near_right, right_ray);
    }
    ScanEdge::appendTo(clear, near_right, near_left, near_edge);
    previous = &reading;
    previous_near_left = near_left;
    previous_left = left;
    previous_left_ray = left_ray;

    ReadingSpans spans{reading.disparity, static_cast<uint32_t>(raster.spans.size()), 0};
    if (reading.hasOccupiedRegion()) {
      const CellPoint far_left = pointAtDepth(axes, left, reading.far_depth_m);
      const CellPoint far_right = pointAtDepth(axes, right, reading.far_depth_m);
      ConvexPolygon occupied;  // counter-clockwise: near right, far right, far left, near left
      occupied.size = 4;
      occupied.vertices = {near_right, far_right, far_left, near_left};
      occupied.edges = {right_ray, EdgeLine::through(far_right, far_left), left_ray, near_edge};
      appendCellSpans(occupied, raster.spans);
    }
    spans.occupied_end = static_cast<uint32_t>(raster.spans.size());
    raster.readings.push_back(spans);
  }
  if (previous != nullptr) {
    ScanEdge::appendTo(clear, previous_near_left, axes.centre, previous_left_ray);
  }
  raster.clear_begin = raster.spans.size();
  appendPolygonSpans(clear, raster.spans);
}

}  // namespace stereonav
