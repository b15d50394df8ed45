#include "rig/camera_rig.h"

#include <mrpt/core/bits_math.h>

#include <sstream>

namespace stereonav {

mrpt::poses::CPose3D CameraRig::opticalPoseOnRobot(double x, double y, double z, double yaw,
                                                   double tilt_down) {
  // Robot frame to a forward-looking optical frame: z_cam = x_robot, x_cam = -y_robot,
  // y_cam = -z_robot. Yaw and tilt are applied in the robot frame first.
  const mrpt::poses::CPose3D mount(x, y, z, yaw, tilt_down, 0.0);
  const mrpt::poses::CPose3D robot_to_optical(0, 0, 0, mrpt::DEG2RAD(-90.0), 0.0,
                                              mrpt::DEG2RAD(-90.0));
  return mount + robot_to_optical;
}

std::vector<SecondaryCamera> parseSecondaryCameras(const std::string& text, const std::string& what) {
  std::vector<SecondaryCamera> cameras;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ';')) {
    if (item.find_first_not_of(" \t") == std::string::npos) continue;
    std::stringstream one(item);
    SecondaryCamera camera;
    std::string extra;
    if (!(one >> camera.bx >> camera.by) || (one >> extra)) {
      throw ConfigError(what + ": expected 'bx by; bx by; ...', got '" + text + "'");
    }
    if (camera.bx == 0.0 && camera.by == 0.0) {
      throw ConfigError(what + ": a secondary camera cannot sit on the reference camera (0 0)");
    }
    cameras.push_back(camera);
  }
  if (cameras.empty()) throw ConfigError(what + ": at least one secondary camera is needed");
  return cameras;
}

CameraRig loadCameraRig(IniSection& section) {
  CameraRig rig;
  auto& camera = rig.reference;
  camera.width = section.getInt("width", camera.width);
  camera.height = section.getInt("height", camera.height);
  camera.focal_px = section.getDouble("focal_px", camera.focal_px);
  camera.cx = section.getDouble("cx", (camera.width - 1) / 2.0);
  camera.cy = section.getDouble("cy", (camera.height - 1) / 2.0);
  rig.baseline_m = section.getDouble("baseline_m", rig.baseline_m);
  const std::string cameras = section.getString("secondary_cameras", "");
  if (!cameras.empty()) {
    rig.secondaries = parseSecondaryCameras(cameras, "[" + section.name() + "] secondary_cameras");
  }
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section.name() + "] " + key + ": " + why);
  };
  if (camera.width <= 0 || camera.height <= 0) fail("width", "image size must be positive");
  if (camera.focal_px <= 0) fail("focal_px", "must be positive");
  if (rig.baseline_m <= 0) fail("baseline_m", "must be positive");
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(
      section.getDouble("mount_x", 0.0), section.getDouble("mount_y", 0.0),
      section.getDouble("mount_z", 0.5), mrpt::DEG2RAD(section.getDouble("mount_yaw_deg", 0.0)),
      mrpt::DEG2RAD(section.getDouble("mount_tilt_deg", 0.0)));
  return rig;
}

}  // namespace stereonav
