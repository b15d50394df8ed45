#include "mapping/stereo_mapper.h"

#include <mrpt/poses/CPose3D.h>

#include "column_projection/virtual_range_scan.h"

namespace stereonav {

StereoMapper::StereoMapper(const MappingOptions& options, const CameraRig& rig)
    : scanner_(rig, options.stereo, options.spike_removal, options.projection),
      scan_max_range_m_(options.projection.scan_max_range_m),
      makes_virtual_scans_(options.grid.model == GridModel::kMrptBayes ||
                           options.mapper.virtual_scans),
      map_(createGridMap(options.grid)),
      disparity_observation_(std::make_shared<CObservationDisparityScan>()),
      virtual_scan_(std::make_shared<mrpt::obs::CObservation2DRangeScan>()) {
  disparity_observation_->camera = DisparityScanCamera::fromRig(rig);
  disparity_observation_->sensorLabel = "STEREO";
  map_input_ = options.grid.model == GridModel::kLinear
                   ? static_cast<const mrpt::obs::CObservation*>(disparity_observation_.get())
                   : virtual_scan_.get();
}

void StereoMapper::process(const RigFrame& frame, const mrpt::poses::CPose2D& robot_pose) {
  observe(frame);
  insertLastObservation(robot_pose);
}

void StereoMapper::observe(const RigFrame& frame) {
  const DisparityScan& scan = scanner_.scan(frame, times_);
  disparity_observation_->scan = scan;
  disparity_observation_->timestamp = frame.timestamp;
  if (makes_virtual_scans_) {
    ScopedStageTimer timer(times_, PipelineStage::kVirtualScan);
    *virtual_scan_ = makeVirtualRangeScan(surfaceReadings(scan), scanner_.rig(), scan_max_range_m_);
    virtual_scan_->timestamp = frame.timestamp;
    virtual_scan_->sensorLabel = kVirtualScanLabel;
  }
}

void StereoMapper::insertLastObservation(const mrpt::poses::CPose2D& robot_pose) {
  {
    ScopedStageTimer timer(times_, PipelineStage::kGridUpdate);
    map_->insertObservation(*map_input_, mrpt::poses::CPose3D(robot_pose));
  }
  times_.countFrame();
}

}  // namespace stereonav
