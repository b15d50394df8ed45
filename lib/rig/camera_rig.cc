#include "rig/camera_rig.h"

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <sstream>

namespace stereonav {

mrpt::math::TVector3D CameraRig::rayOnRobot(double x, double y) const {
  const double u = (x - reference.cx) / reference.focal_px;
  const double v = (y - reference.cy) / reference.focal_px;
  const auto rotation = pose_on_robot.getRotationMatrix();
  return {rotation(0, 0) * u + rotation(0, 1) * v + rotation(0, 2),
          rotation(1, 0) * u + rotation(1, 1) * v + rotation(1, 2),
          rotation(2, 0) * u + rotation(2, 1) * v + rotation(2, 2)};
}

std::optional<mrpt::math::TPoint2D> CameraRig::floorPointOnRobot(double x, double y) const {
  const mrpt::math::TVector3D ray = rayOnRobot(x, y);
  const auto sensor = pose_on_robot.translation();
  if (ray.z >= 0.0 || sensor.z <= 0.0) return std::nullopt;
  const double depth = -sensor.z / ray.z;
  return mrpt::math::TPoint2D(sensor.x + depth * ray.x, sensor.y + depth * ray.y);
}

mrpt::math::TPoint2D CameraRig::readingOnRobot(double x, double y, double disparity) const {
  const mrpt::math::TVector3D ray = rayOnRobot(x, y);
  const double depth = depthForDisparity(disparity);
  const auto sensor = pose_on_robot.translation();
  return mrpt::math::TPoint2D(sensor.x + depth * ray.x, sensor.y + depth * ray.y);
}

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
    std::string bx, by;
    if (!(one >> bx >> by) || (one >> extra) || !parseFiniteDouble(bx, camera.bx) ||
        !parseFiniteDouble(by, camera.by)) {
      throw ConfigError(what + ": expected 'bx by; bx by; ...', got '" + text + "'");
    }
    if (std::abs(camera.bx) > kMaxRelativeBaseline || std::abs(camera.by) > kMaxRelativeBaseline) {
      throw ConfigError(what + ": bx and by must be in " +
                        describeRange(-kMaxRelativeBaseline, kMaxRelativeBaseline) + ", got '" + text + "'");
    }
    if (camera.bx == 0.0 && camera.by == 0.0) {
      throw ConfigError(what + ": a secondary camera cannot sit on the reference camera (0 0)");
    }
    cameras.push_back(camera);
  }
  if (cameras.empty()) throw ConfigError(what + ": at least one secondary camera is needed");
  return cameras;
}

namespace {

constexpr double kMinFocalPx = 1e-3, kMaxFocalPx = 1e6;
constexpr double kMinBaselineM = 1e-4, kMaxBaselineM = 100.0;
constexpr double kMaxMountOffsetM = 100.0;

}  // namespace

std::string implausibleRig(const CameraRig& rig) {
  const PinholeCamera& camera = rig.reference;
  if (camera.width < 1 || camera.width > kMaxImageSide || camera.height < 1 || camera.height > kMaxImageSide) {
    return "image size " + std::to_string(camera.width) + "x" + std::to_string(camera.height) + " outside 1.." +
           std::to_string(kMaxImageSide);
  }
  if (!(camera.focal_px >= kMinFocalPx && camera.focal_px <= kMaxFocalPx)) {
    return "focal length " + std::to_string(camera.focal_px) + " px outside " + describeRange(kMinFocalPx, kMaxFocalPx);
  }
  if (!(std::abs(camera.cx) <= 2.0 * camera.width && std::abs(camera.cy) <= 2.0 * camera.height)) {
    return "principal point far outside the image";
  }
  if (!(rig.baseline_m >= kMinBaselineM && rig.baseline_m <= kMaxBaselineM)) {
    return "baseline " + std::to_string(rig.baseline_m) + " m outside " + describeRange(kMinBaselineM, kMaxBaselineM);
  }
  for (const SecondaryCamera& secondary : rig.secondaries) {
    if (!(std::abs(secondary.bx) <= kMaxRelativeBaseline && std::abs(secondary.by) <= kMaxRelativeBaseline)) {
      return "a secondary camera more than " + std::to_string(static_cast<int>(kMaxRelativeBaseline)) +
             " baselines away";
    }
  }
  const auto& pose = rig.pose_on_robot;
  for (const double value : {pose.x(), pose.y(), pose.z(), pose.yaw(), pose.pitch(), pose.roll()}) {
    if (!(std::abs(value) <= kMaxMountOffsetM)) return "camera pose on the robot not finite or too far";
  }
  return "";
}

CameraRig loadCameraRig(IniSection& section) {
  CameraRig rig;
  auto& camera = rig.reference;
  // Ranges: physically sensible bounds that also keep every derived size finite and small
  // (image buffers, f B / d, the mount pose).
  camera.width = section.getInt("width", camera.width, 1, kMaxImageSide);
  camera.height = section.getInt("height", camera.height, 1, kMaxImageSide);
  camera.focal_px = section.getDouble("focal_px", camera.focal_px, kMinFocalPx, kMaxFocalPx);
  camera.cx = section.getDouble("cx", (camera.width - 1) / 2.0, -camera.width, 2.0 * camera.width);
  camera.cy = section.getDouble("cy", (camera.height - 1) / 2.0, -camera.height, 2.0 * camera.height);
  rig.baseline_m = section.getDouble("baseline_m", rig.baseline_m, kMinBaselineM, kMaxBaselineM);
  const std::string cameras = section.getString("secondary_cameras", "");
  if (!cameras.empty()) {
    rig.secondaries = parseSecondaryCameras(cameras, "[" + section.name() + "] secondary_cameras");
  }
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(
      section.getDouble("mount_x", 0.0, -kMaxMountOffsetM, kMaxMountOffsetM),
      section.getDouble("mount_y", 0.0, -kMaxMountOffsetM, kMaxMountOffsetM),
      section.getDouble("mount_z", 0.5, -kMaxMountOffsetM, kMaxMountOffsetM),
      mrpt::DEG2RAD(section.getDouble("mount_yaw_deg", 0.0, -360.0, 360.0)),
      mrpt::DEG2RAD(section.getDouble("mount_tilt_deg", 0.0, -90.0, 90.0)));
  return rig;
}

}  // namespace stereonav
