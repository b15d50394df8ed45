#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CSerializable.h>

#include "column_projection/disparity_scan.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav {

// A disparity scan as an MRPT observation, so that it travels in rawlogs and sensory frames and
// is inserted into metric maps like any other sensor reading. It carries the camera values the
// sensor model needs; the sensor pose is the reference camera's OPTICAL frame on the robot, as in
// mrpt::obs::CObservationStereoImages::cameraPose.
class CObservationDisparityScan : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationDisparityScan, stereonav)

 public:
  DisparityScan scan;
  DisparityScanCamera camera;

  void getSensorPose(mrpt::poses::CPose3D& out_sensor_pose) const override {
    out_sensor_pose = camera.pose_on_robot;
  }
  void setSensorPose(const mrpt::poses::CPose3D& sensor_pose) override {
    camera.pose_on_robot = sensor_pose;
  }
  void getDescriptionAsText(std::ostream& o) const override;
};

}  // namespace stereonav
