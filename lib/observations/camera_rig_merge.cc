#include "observations/camera_rig_merge.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace stereonav {
namespace {

// Angle of the rotation taking one orientation to the other.
double rotationAngleBetween(const mrpt::poses::CPose3D& a, const mrpt::poses::CPose3D& b) {
  const auto relative = (a - b).getRotationMatrix();
  const double cosine = (relative(0, 0) + relative(1, 1) + relative(2, 2) - 1.0) / 2.0;
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

class MismatchReport {
 public:
  explicit MismatchReport(std::vector<std::string>& warnings) : warnings_(warnings) {}

  void compare(const std::string& what, double ini, double observed, double tolerance,
               const std::string& unit) {
    if (std::abs(ini - observed) <= tolerance) return;
    std::ostringstream line;
    line << what << ": ini " << ini << " " << unit << ", rawlog " << observed << " " << unit
         << " (differ by more than " << tolerance << " " << unit << "); using the ini value";
    warnings_.push_back(line.str());
  }

  void add(const std::string& line) { warnings_.push_back(line + "; using the ini value"); }

 private:
  std::vector<std::string>& warnings_;
};

}  // namespace

CalibrationTolerance loadCalibrationTolerance(IniSection& section) {
  CalibrationTolerance tolerance;
  const auto load = [&](const std::string& key, double& value) {
    value = section.getNonNegative(key, value);
  };
  load("tolerance_focal_px", tolerance.focal_px);
  load("tolerance_principal_point_px", tolerance.principal_point_px);
  load("tolerance_baseline_m", tolerance.baseline_m);
  load("tolerance_position_m", tolerance.position_m);
  load("tolerance_angle_deg", tolerance.angle_deg);
  return tolerance;
}

MergedCameraRig mergeCameraRigs(const std::optional<CameraRig>& from_ini,
                                const std::optional<CameraRig>& observed,
                                const CalibrationTolerance& tolerance) {
  if (!from_ini && !observed) {
    throw std::invalid_argument("no camera rig: give a [rig] section or a rawlog with calibration");
  }
  MergedCameraRig merged{from_ini ? *from_ini : *observed, {}};
  if (!from_ini || !observed) return merged;

  const CameraRig& ini = *from_ini;
  const CameraRig& rec = *observed;
  MismatchReport report(merged.warnings);
  if (ini.reference.width != rec.reference.width || ini.reference.height != rec.reference.height) {
    report.add("image size: ini " + std::to_string(ini.reference.width) + "x" +
               std::to_string(ini.reference.height) + ", rawlog " +
               std::to_string(rec.reference.width) + "x" + std::to_string(rec.reference.height));
  }
  report.compare("focal length", ini.reference.focal_px, rec.reference.focal_px, tolerance.focal_px,
                 "px");
  report.compare("principal point x", ini.reference.cx, rec.reference.cx,
                 tolerance.principal_point_px, "px");
  report.compare("principal point y", ini.reference.cy, rec.reference.cy,
                 tolerance.principal_point_px, "px");
  report.compare("baseline", ini.baseline_m, rec.baseline_m, tolerance.baseline_m, "m");

  if (ini.secondaries.size() != rec.secondaries.size()) {
    report.add("secondary cameras: ini has " + std::to_string(ini.secondaries.size()) +
               ", rawlog " + std::to_string(rec.secondaries.size()));
  } else {
    for (size_t i = 0; i < ini.secondaries.size(); ++i) {
      // Compare where the cameras are (metres), not bx/by, which depend on each side's B.
      const std::string what = "secondary camera " + std::to_string(i) + " offset";
      report.compare(what + " x", ini.secondaries[i].bx * ini.baseline_m,
                     rec.secondaries[i].bx * rec.baseline_m, tolerance.position_m, "m");
      report.compare(what + " y", ini.secondaries[i].by * ini.baseline_m,
                     rec.secondaries[i].by * rec.baseline_m, tolerance.position_m, "m");
    }
  }

  const double distance = ini.pose_on_robot.distanceTo(rec.pose_on_robot);
  if (distance > tolerance.position_m) {
    std::ostringstream line;
    line << "camera position on the robot: ini " << ini.pose_on_robot.translation().asString()
         << ", rawlog " << rec.pose_on_robot.translation().asString() << " (" << distance
         << " m apart, more than " << tolerance.position_m << " m)";
    report.add(line.str());
  }
  const double angle = mrpt::RAD2DEG(rotationAngleBetween(ini.pose_on_robot, rec.pose_on_robot));
  if (angle > tolerance.angle_deg) {
    std::ostringstream line;
    line << "camera orientation on the robot: ini and rawlog differ by " << angle
         << " deg (more than " << tolerance.angle_deg << " deg)";
    report.add(line.str());
  }
  return merged;
}

}  // namespace stereonav
