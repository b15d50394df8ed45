#include "sensor_model/stereo_sensor_model.h"

#include <mrpt/math/CMatrixFixed.h>

#include <algorithm>
#include <cmath>

namespace stereonav {

namespace {

// The camera's floor frame expressed in some target frame (world or cell units): its centre,
// its heading and the image-right direction, per metre.
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

// The slope of the line of sight through image column boundary `edge_x` (a pixel edge, x +/-
// 0.5) on the floor: per metre of depth Z it moves (edge_x - cx) / f metres to the image right
// and floor_per_depth metres forward (paper section 3.2); `metres_per_pixel_edge` is
// 1 / (f floor_per_depth), one division shared by a reading's two edges.
double edgeSlope(const DisparityScanCamera& camera, double edge_x, double metres_per_pixel_edge) {
  return (edge_x - camera.cx) * metres_per_pixel_edge;
}

// A line of sight on the floor per metre forward.
CellPoint lineOfSight(const FloorAxes& axes, double slope) {
  return {axes.forward.u + slope * axes.image_right.u, axes.forward.v + slope * axes.image_right.v};
}

CellPoint pointAt(const FloorAxes& axes, const CellPoint& line_of_sight, double forward_m) {
  return {axes.centre.u + forward_m * line_of_sight.u, axes.centre.v + forward_m * line_of_sight.v};
}

EdgeLine rayLine(const FloorAxes& axes, const CellPoint& line_of_sight) {
  return {axes.centre.u, axes.centre.v, line_of_sight.u / line_of_sight.v};
}

mrpt::math::TPoint2D toPoint(const CellPoint& p) { return {p.u, p.v}; }

// The cells a corner span of an OCC region touches: corner (i, j) is the lower-left corner of
// cell (i, j), so corners [begin, end) of corner row j are corners of the cells [begin - 1, end)
// of rows j - 1 and j.
void appendTouchedCells(const CellSpanBuffer& corners, std::vector<CellSpan>& cells) {
  for (const CellSpan& corner : corners) {
    cells.push_back({corner.row - 1, corner.col_begin - 1, corner.col_end});
    cells.push_back({corner.row, corner.col_begin - 1, corner.col_end});
  }
}

// `clear` (sorted by row, then column, as appendPolygonSpans leaves it) without the cells of
// `kept` (sorted by row, then column begin; they may overlap), appended to `out`.
void appendSpansWithout(const CellSpanBuffer& clear, const std::vector<CellSpan>& kept,
                        CellSpanBuffer& out) {
  const auto emit = [&](int row, int begin, int end) {
    CellSpan* span = out.room(1);
    *span = {row, begin, end};
    out.commit(span + 1);
  };
  auto row_first = kept.begin();
  for (const CellSpan& span : clear) {
    while (row_first != kept.end() && row_first->row < span.row) ++row_first;
    int from = span.col_begin;
    for (auto k = row_first; k != kept.end() && k->row == span.row && from < span.col_end; ++k) {
      if (k->col_end <= from) continue;
      if (k->col_begin >= span.col_end) break;
      if (k->col_begin > from) emit(span.row, from, k->col_begin);
      from = std::max(from, k->col_end);
    }
    if (from < span.col_end) emit(span.row, from, span.col_end);
  }
}

const GridFrame kMetricFrame{0.0, 0.0, 1.0};

// One side of a column's wedge: its near corner, its line of sight and that line as an edge.
struct WedgeSide {
  CellPoint near;
  CellPoint line_of_sight;
  EdgeLine ray;
};

// Counter-clockwise: near right, far right, far left, near left.
ConvexPolygon occupiedRegion(const FloorAxes& axes, const ColumnReading& reading, const WedgeSide& right,
                             const WedgeSide& left, const EdgeLine& near_edge) {
  const CellPoint far_left = pointAt(axes, left.line_of_sight, reading.farDistance());
  const CellPoint far_right = pointAt(axes, right.line_of_sight, reading.farDistance());
  ConvexPolygon occupied;
  occupied.size = 4;
  occupied.vertices = {right.near, far_right, far_left, left.near};
  occupied.edges = {right.ray, EdgeLine::through(far_right, far_left), left.ray, near_edge};
  return occupied;
}

// Moved by half a cell, the region has the grid's cell corners at its cell centres.
ConvexPolygon shiftedHalfACell(ConvexPolygon polygon) {
  for (CellPoint& vertex : polygon.vertices) {
    vertex.u += 0.5;
    vertex.v += 0.5;
  }
  for (EdgeLine& edge : polygon.edges) {
    edge.u0 += 0.5;
    edge.v0 += 0.5;
  }
  return polygon;
}

// The CLEAR union's spans after the occupied ones; with obstacle borders kept, without the cells
// an occupied region's corners touch.
void appendClearSpans(bool keep_obstacle_borders, const CellWindow& window, ScanRaster& raster) {
  if (!keep_obstacle_borders) {
    appendPolygonSpans(raster.clear_edges, raster.spans, window, &raster.clear_scan);
    return;
  }
  raster.clear_cells.clear();
  appendPolygonSpans(raster.clear_edges, raster.clear_cells, window, &raster.clear_scan);
  raster.border_cells.clear();
  appendTouchedCells(raster.occupied_corners, raster.border_cells);
  std::sort(raster.border_cells.begin(), raster.border_cells.end(),
            [](const CellSpan& a, const CellSpan& b) {
              return a.row != b.row ? a.row < b.row : a.col_begin < b.col_begin;
            });
  appendSpansWithout(raster.clear_cells, raster.border_cells, raster.spans);
}

}  // namespace

HeadTilt HeadTilt::of(const mrpt::poses::CPose3D& optical_pose_on_robot) {
  const auto rotation = optical_pose_on_robot.getRotationMatrix();
  // Heights (robot z) of the optical axis (column 2) and of the image-down axis (column 1):
  // -sin t and -cos t when the head does not roll.
  const double tilt = std::atan2(-rotation(2, 2), -rotation(2, 1));
  return {std::cos(tilt), std::sin(tilt)};
}

DisparityScanCamera DisparityScanCamera::fromRig(const CameraRig& rig) {
  DisparityScanCamera camera;
  camera.focal_px = rig.reference.focal_px;
  camera.cx = rig.reference.cx;
  camera.cy = rig.reference.cy;
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
                                                     const DisparityScanCamera& camera,
                                                     std::optional<int> row) const {
  return reading(column, disparity, camera, HeadTilt::of(camera.pose_on_robot),
                 row ? *row : camera.cy);
}

ColumnReading StereoSensorModel::reading(int column, float disparity,
                                         const DisparityScanCamera& camera, const HeadTilt& tilt,
                                         double row) const {
  ColumnReading reading;
  reading.column = column;
  reading.disparity = disparity;
  if (isValidDisparity(disparity)) {
    const double uncertainty = options_.disparity_uncertainty_px;
    reading.near_depth_m = camera.depthForDisparity(disparity + uncertainty);
    // Equation 1 with d - u <= 0 puts the obstacle out to infinity, and just above it
    // kilometres away: the region stops at max_range_m.
    reading.far_depth_m = disparity > uncertainty
                              ? std::min(camera.depthForDisparity(disparity - uncertainty),
                                         options_.max_range_m)
                              : options_.max_range_m;
    reading.far_depth_m = std::max(reading.far_depth_m, reading.near_depth_m);
  } else {
    reading.near_depth_m = reading.far_depth_m = options_.clear_invalid_columns_to_m;
  }
  reading.floor_per_depth = tilt.cos_tilt - (row - camera.cy) / camera.focal_px * tilt.sin_tilt;
  const double metres_per_pixel_edge = 1.0 / (camera.focal_px * reading.floor_per_depth);
  reading.left_slope = edgeSlope(camera, column - 0.5, metres_per_pixel_edge);
  reading.right_slope = edgeSlope(camera, column + 0.5, metres_per_pixel_edge);
  return reading;
}

void StereoSensorModel::readings(const DisparityScan& scan, const DisparityScanCamera& camera,
                                 std::vector<ColumnReading>& readings) const {
  readings.clear();
  const HeadTilt tilt = HeadTilt::of(camera.pose_on_robot);
  const bool has_rows = scan.column_row.size() == scan.column_disparity.size();
  for (int column = 0; column < scan.columns(); ++column) {
    const float disparity = scan.column_disparity[column];
    // A surface nearer than the matcher's range reads at its top: somewhere nearer than the
    // reading says (a wall 0.4 m ahead reads 0.51 m at 31 px), so neither its CLEAR nor its OCC
    // region is where the surface is.
    if (scan.atRangeTop(column)) continue;
    if (isValidDisparity(disparity) && disparity >= 0.0f) {
      const int row = has_rows ? scan.column_row[column] : -1;
      readings.push_back(reading(column, disparity, camera, tilt, row >= 0 ? row : camera.cy));
    } else if (options_.clear_invalid_columns_to_m > 0.0) {
      readings.push_back(reading(column, kInvalidDisparity, camera, tilt, camera.cy));
    } else {
      continue;
    }
    if (scan.endsClear(column)) {
      const int row = scan.column_clear_end_row[column];
      const double floor_per_depth =
          tilt.cos_tilt - ((row >= 0 ? row : camera.cy) - camera.cy) / camera.focal_px * tilt.sin_tilt;
      readings.back().clear_end_m =
          camera.depthForDisparity(scan.column_clear_end[column]) * floor_per_depth;
    }
  }
  shareEdgeRays(readings);
}

void StereoSensorModel::shareEdgeRays(std::vector<ColumnReading>& readings) const {
  // A level head (or readings all from one row) already gives neighbours the same ray, in
  // image order: nothing to do.
  bool in_order = true;
  for (size_t i = 0; i < readings.size() && in_order; ++i) {
    const ColumnReading& reading = readings[i];
    in_order = reading.left_slope <= reading.right_slope;
    if (i > 0 && in_order) {
      const ColumnReading& previous = readings[i - 1];
      in_order = previous.column + 1 == reading.column
                     ? previous.right_slope == reading.left_slope
                     : previous.right_slope <= reading.left_slope;
    }
  }
  if (in_order) return;
  // The distinct pixel edges in image order, left to right: a reading's left edge (unless it is
  // the previous reading's right edge: adjacent columns), then its right edge.
  std::vector<EdgeRay>& edges = edge_rays_;
  edges.clear();
  for (size_t i = 0; i < readings.size(); ++i) {
    const ColumnReading& reading = readings[i];
    const EdgeRay left{reading.left_slope, reading.nearDistance(), reading.column};
    if (i == 0 || readings[i - 1].column + 1 != reading.column) {
      edges.push_back(left);
    } else if (left.nearerThan(edges.back())) {
      edges.back() = left;
    }
    edges.push_back({reading.right_slope, reading.nearDistance(), reading.column});
  }
  // Slopes must not decrease from left to right. Where two neighbouring edges disagree, the one
  // from the farther reading takes the nearer one's ray; every such step moves a ray to an edge
  // whose owner was farther, so the sweeps end.
  const auto order = [](EdgeRay& left, EdgeRay& right) {
    if (!(left.slope > right.slope)) return false;
    if (left.nearerThan(right)) {
      right = left;
    } else {
      left = right;
    }
    return true;
  };
  for (bool changed = !edges.empty(); changed;) {
    changed = false;
    for (size_t k = 1; k < edges.size(); ++k) changed |= order(edges[k - 1], edges[k]);
    for (size_t k = edges.size() - 1; k > 0; --k) changed |= order(edges[k - 1], edges[k]);
  }
  size_t edge = 0;
  for (size_t i = 0; i < readings.size(); ++i) {
    if (i > 0 && readings[i - 1].column + 1 != readings[i].column) ++edge;
    readings[i].left_slope = edges[edge].slope;
    readings[i].right_slope = edges[++edge].slope;
  }
}

RegionCorners StereoSensorModel::corners(const ColumnReading& reading,
                                         const mrpt::poses::CPose2D& camera_floor_pose) const {
  const FloorAxes axes = floorAxes(camera_floor_pose, kMetricFrame);
  const CellPoint left = lineOfSight(axes, reading.left_slope);
  const CellPoint right = lineOfSight(axes, reading.right_slope);
  return {toPoint(pointAt(axes, left, reading.nearDistance())),
          toPoint(pointAt(axes, right, reading.nearDistance())),
          toPoint(pointAt(axes, left, reading.farDistance())),
          toPoint(pointAt(axes, right, reading.farDistance()))};
}

WorldBounds StereoSensorModel::bounds(const std::vector<ColumnReading>& readings,
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
    include(pointAt(axes, lineOfSight(axes, reading.left_slope), reading.farDistance()));
    include(pointAt(axes, lineOfSight(axes, reading.right_slope), reading.farDistance()));
  }
  return bounds;
}

void StereoSensorModel::rasterize(const std::vector<ColumnReading>& readings,
                                  const mrpt::poses::CPose2D& camera_floor_pose,
                                  const GridFrame& frame, ScanRaster& raster,
                                  const CellWindow& window) const {
  raster.readings.clear();
  raster.spans.clear();
  raster.clear_edges.clear();
  raster.occupied_corners.clear();
  const FloorAxes axes = floorAxes(camera_floor_pose, frame);
  std::vector<ScanEdge>& clear = raster.clear_edges;
  // Walk the columns from image right to image left: counter-clockwise around the camera. The
  // CLEAR union's outline runs camera -> near right -> near left -> (along the shared line of
  // sight) the next column's near right ... -> camera, returning to the camera at every gap.
  const ColumnReading* previous = nullptr;
  CellPoint previous_clear_left{};
  CellPoint previous_left{};
  EdgeLine previous_left_ray{};
  for (auto it = readings.rbegin(); it != readings.rend(); ++it) {
    const ColumnReading& reading = *it;
    // Neighbouring columns share the line of sight through their common pixel edge (readings()
    // gave both the same slope): the one to the right hands its left line over, so both sides
    // of the edge use one EdgeLine.
    const bool adjacent = previous != nullptr && previous->column == reading.column + 1;
    const CellPoint right = adjacent ? previous_left : lineOfSight(axes, reading.right_slope);
    const EdgeLine right_ray = adjacent ? previous_left_ray : rayLine(axes, right);
    const CellPoint left = lineOfSight(axes, reading.left_slope);
    const EdgeLine left_ray = rayLine(axes, left);
    const CellPoint near_left = pointAt(axes, left, reading.nearDistance());
    const CellPoint near_right = pointAt(axes, right, reading.nearDistance());
    const double clear_distance = reading.clearDistance();
    const CellPoint clear_left = pointAt(axes, left, clear_distance);
    const CellPoint clear_right = pointAt(axes, right, clear_distance);
    // A column hidden behind a nearer neighbour's silhouette has an empty wedge (left = right).
    const bool has_width = reading.right_slope > reading.left_slope;
    const EdgeLine near_edge = has_width ? EdgeLine::through(near_left, near_right) : EdgeLine{};

    if (adjacent) {
      ScanEdge::appendTo(clear, previous_clear_left, clear_right, right_ray);
    } else {
      if (previous != nullptr) {
        ScanEdge::appendTo(clear, previous_clear_left, axes.centre, previous_left_ray);
      }
      ScanEdge::appendTo(clear, axes.centre, clear_right, right_ray);
    }
    if (has_width) ScanEdge::appendTo(clear, clear_right, clear_left, EdgeLine::through(clear_left, clear_right));
    previous = &reading;
    previous_clear_left = clear_left;
    previous_left = left;
    previous_left_ray = left_ray;

    ReadingSpans spans{reading.disparity, static_cast<uint32_t>(raster.spans.size()), 0};
    if (reading.hasOccupiedRegion()) {
      const ConvexPolygon occupied =
          occupiedRegion(axes, reading, {near_right, right, right_ray}, {near_left, left, left_ray}, near_edge);
      appendCellSpans(occupied, raster.spans, window);
      if (options_.keep_obstacle_borders) appendCellSpans(shiftedHalfACell(occupied), raster.occupied_corners);
    }
    spans.occupied_end = static_cast<uint32_t>(raster.spans.size());
    raster.readings.push_back(spans);
  }
  if (previous != nullptr) {
    ScanEdge::appendTo(clear, previous_clear_left, axes.centre, previous_left_ray);
  }
  raster.clear_begin = raster.spans.size();
  appendClearSpans(options_.keep_obstacle_borders, window, raster);
}

}  // namespace stereonav
