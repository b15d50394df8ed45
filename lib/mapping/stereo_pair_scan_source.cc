#include "mapping/stereo_pair_scan_source.h"

#include <mrpt/obs/CObservationStereoImages.h>

#include "observations/camera_rig_merge.h"
#include "observations/rig_observations.h"

namespace stereonav {

StereoPairScanSource::StereoPairScanSource(const MappingOptions& options,
                                           std::string images_directory)
    : options_(options),
      images_directory_(std::move(images_directory)),
      rectifier_(options.calibration) {
  if (options_.rig) options_.rig->secondaries.resize(1);
}

CObservationDisparityScan::Ptr StereoPairScanSource::toDisparityScan(
    const mrpt::obs::CObservation& observation) const {
  const auto* pair = dynamic_cast<const mrpt::obs::CObservationStereoImages*>(&observation);
  if (pair == nullptr) return nullptr;
  // Pairs we did not record do not say which camera is the reference: the ini's rig does (a
  // secondary on the left, bx < 0, makes the right camera the reference, as on the Triclops).
  const PairReference unnamed_reference =
      options_.rig && options_.rig->secondaries.front().bx < 0.0 ? PairReference::kRight
                                                                 : PairReference::kLeft;
  const RigFrame frame = fromRigObservations(*pair, {}, images_directory_, unnamed_reference, rectifier_);

  std::lock_guard<std::mutex> lock(mutex_);
  if (!scanner_) {
    const CameraRig rig = mergeCameraRigs(options_.rig, frame.rig, options_.calibration_tolerance).rig;
    scanner_.emplace(rig, options_.stereo, options_.spike_removal, options_.projection);
    camera_ = DisparityScanCamera::fromRig(rig);
  }
  auto scan = std::make_shared<CObservationDisparityScan>();
  scan->scan = scanner_->scan(frame, times_);
  scan->camera = camera_;
  scan->timestamp = pair->timestamp;
  scan->sensorLabel = pair->sensorLabel;
  return scan;
}

}  // namespace stereonav
