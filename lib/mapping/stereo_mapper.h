#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>

#include "mapping/disparity_scanner.h"
#include "mapping/mapping_options.h"
#include "mapping/stage_times.h"
#include "observations/rig_frame.h"
#include "occupancy_grid/observation_disparity_scan.h"

namespace stereonav {

// The whole per-frame pipeline (paper figure 5, then section 3.4): rig frame -> disparity ->
// spike removal -> column projection -> map update at the robot's pose. The map is the model
// chosen in [grid]: the paper's linear grid takes the disparity scan itself, MRPT's Bayesian
// COccupancyGridMap2D takes the scan as a virtual laser (column_projection/virtual_range_scan.h).
// Observations and buffers are kept between frames; time spent per stage is recorded.
class StereoMapper {
 public:
  // `rig` is the calibration to map with (e.g. mergeCameraRigs of the ini and the rawlog).
  StereoMapper(const MappingOptions& options, const CameraRig& rig);

  // Maps one frame taken with the robot at `robot_pose` (its odometry pose: the paper maps with
  // dead reckoning, section 5).
  void process(const RigFrame& frame, const mrpt::poses::CPose2D& robot_pose);

  // process() in its two halves, for a caller that needs the frame's scan before it knows the
  // pose (a localizer matching the scan against the map): observe() runs the frame through the
  // pipeline up to the scans, insertLastObservation() puts them into the map.
  void observe(const RigFrame& frame);
  void insertLastObservation(const mrpt::poses::CPose2D& robot_pose);

  const DisparityScanner& scanner() const { return scanner_; }
  // The last frame's scan as an MRPT observation, in the robot frame.
  const CObservationDisparityScan& disparityScan() const { return *disparity_observation_; }
  // The last frame's virtual laser scan; nullptr unless the grid model or
  // MapperOptions::virtual_scans asked for it.
  const mrpt::obs::CObservation2DRangeScan* virtualScan() const {
    return makes_virtual_scans_ ? virtual_scan_.get() : nullptr;
  }
  const mrpt::maps::CMetricMap& map() const { return *map_; }
  const StageTimes& times() const { return times_; }
  size_t framesMapped() const { return times_.frames(); }

 private:
  DisparityScanner scanner_;
  double scan_max_range_m_;
  bool makes_virtual_scans_;
  mrpt::maps::CMetricMap::Ptr map_;
  // The observation the map takes, re-filled every frame.
  const mrpt::obs::CObservation* map_input_;
  CObservationDisparityScan::Ptr disparity_observation_;
  mrpt::obs::CObservation2DRangeScan::Ptr virtual_scan_;
  StageTimes times_;
};

// The label of the virtual laser scans (in the map's observations and in recorded rawlogs).
constexpr const char* kVirtualScanLabel = "STEREO_SCAN";

}  // namespace stereonav
