#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CSerializable.h>

#include <string>
#include <vector>

namespace stereonav {

// Collects one virtual laser scan per frame with the odometry pose it was taken at, and saves
// them as an observations-only rawlog (https://docs.mrpt.org/reference/latest/
// robotics_file_formats.html) that stock MRPT apps read, e.g. icp-slam with
// ini/icp_slam_virtual_scans.ini: per frame a CObservationOdometry labelled "ODOMETRY" (absolute
// pose) followed by the CObservation2DRangeScan, both with the frame's timestamp. Kept in memory
// (about 2 kB per frame) so the file is written in one go, atomically.
class VirtualScanRecorder {
 public:
  void add(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& odometry);
  size_t size() const { return observations_.size() / 2; }
  // gzip-compressed like MRPT's own rawlogs; throws std::runtime_error naming `path` on failure.
  void save(const std::string& path) const;

 private:
  std::vector<mrpt::serialization::CSerializable::Ptr> observations_;
};

}  // namespace stereonav
