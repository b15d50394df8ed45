#pragma once

#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "column_projection/disparity_scan.h"
#include "occupancy_grid/disparity_tagged_grid.h"
#include "occupancy_grid/grid_options.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav {

// Inserts disparity scans into a DisparityTaggedGrid with the paper's linear update rule
// (section 3.4): for every reading r, G += K over OCC(r) and G -= K over CLEAR(r), clipped to
// [g_min, g_max].
//
// Accuracy preservation (section 4.3), decided region-wise as the paper describes it: before
// applying r's OCC update, look at every cell of OCC(r); if any holds obstacle evidence
// (G above the unknown midpoint) whose tag is a higher disparity than r's (a closer, more
// precise reading), that evidence already explains r and the whole OCC update is skipped.
// Otherwise G += K and the tag becomes r's disparity on every cell of OCC(r).
// CLEAR never changes tags: a tag only counts while its cell still holds obstacle evidence, so
// once clearing has brought G back to unknown or below the tag is inert and a moved obstacle no
// longer blocks new readings. CLEAR is applied even when OCC is skipped.
//
// Free-space preservation (GridUpdateOptions::free_preservation_range_m = R > 0) carries the
// same hypothesis-explanation argument over to free space: a cell CLEAR reached within R of the
// camera was seen free from close, so an obstacle hypothesised from farther than R (a region
// metres deep, or a ghost match) is not there but in the rest of its region. Such a reading's
// OCC update spares those cells. An OCC update from within R is applied as usual and makes its
// cells ordinary again, so an obstacle that moves in is mapped once it is seen from close.
class DisparityScanInserter {
 public:
  DisparityScanInserter(const SensorModelOptions& sensor_model, const GridUpdateOptions& update,
                        double growth_margin_m);

  // `robot_pose` is the robot's pose in the grid's world frame; the camera's pose on the robot
  // comes with `camera`. Grows the grid first if the regions leave it.
  void insert(const DisparityScan& scan, const DisparityScanCamera& camera,
              const mrpt::poses::CPose2D& robot_pose, DisparityTaggedGrid& grid);

 private:
  void clearCells(const CellSpan* begin, const CellSpan* end, double camera_col,
                  double camera_row, DisparityTaggedGrid& grid) const;
  bool explainedByBetterEvidence(const CellSpan* begin, const CellSpan* end, float disparity,
                                 const DisparityTaggedGrid& grid) const;
  void occupyCells(const CellSpan* begin, const CellSpan* end, float disparity,
                   bool spare_close_free, DisparityTaggedGrid& grid) const;

  StereoSensorModel model_;
  GridUpdateOptions update_;
  double growth_margin_m_;
  // Scratch kept between scans so that inserting allocates nothing once warmed up.
  std::vector<ColumnReading> readings_;
  ScanRaster raster_;
};

}  // namespace stereonav
