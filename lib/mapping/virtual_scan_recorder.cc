#include "mapping/virtual_scan_recorder.h"

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

#include "common/atomic_file.h"

namespace stereonav {

void VirtualScanRecorder::add(const mrpt::obs::CObservation2DRangeScan& scan,
                              const mrpt::poses::CPose2D& odometry) {
  auto odometry_observation = std::make_shared<mrpt::obs::CObservationOdometry>();
  odometry_observation->sensorLabel = "ODOMETRY";
  odometry_observation->timestamp = scan.timestamp;
  odometry_observation->odometry = odometry;
  observations_.push_back(odometry_observation);
  observations_.push_back(std::make_shared<mrpt::obs::CObservation2DRangeScan>(scan));
}

void VirtualScanRecorder::save(const std::string& path) const {
  writeGzArchiveAtomically(path, [&](mrpt::serialization::CArchive& archive) {
    for (const auto& observation : observations_) archive << *observation;
  });
}

}  // namespace stereonav
