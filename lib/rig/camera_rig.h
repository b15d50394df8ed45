#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/poses/CPose3D.h>

#include <optional>
#include <string>
#include <vector>

#include "common/ini_section.h"

namespace stereonav {

// Rectified pinhole camera with square pixels (paper section 2.1: the Triclops corrects lens
// distortion and misalignment so that all three images conform to this model).
struct PinholeCamera {
  int width = 320;
  int height = 240;
  double focal_px = 160.0;  // f, in pixels
  double cx = 159.5;        // principal point, pixels
  double cy = 119.5;
};

// Where a secondary camera sits relative to the reference camera, in units of the rig's unit
// baseline, along the reference image axes (x right, y down). A scene point at disparity d (for
// the unit baseline) seen at (x, y) in the reference appears at (x - bx*d, y - by*d) here.
// Binocular: {1, 0}. Triclops L-shape (reference = right camera): left {-1, 0}, top {0, -1}.
struct SecondaryCamera {
  double bx = 1.0;
  double by = 0.0;
};

// Bound on |bx| and |by|: a secondary camera at most this many unit baselines away. It keeps
// bx*d a sensible pixel offset (a 1e9 baseline would overflow the matcher's pixel arithmetic).
constexpr double kMaxRelativeBaseline = 1000.0;
// Bound on the reference image's width and height, pixels.
constexpr int kMaxImageSide = 16384;

// The whole head: the reference camera, its secondary cameras, and where it is on the robot.
struct CameraRig {
  PinholeCamera reference;
  double baseline_m = 0.10;  // B: the unit baseline, metres
  std::vector<SecondaryCamera> secondaries{{-1.0, 0.0}, {0.0, -1.0}};
  // Pose of the reference camera's optical frame (x right, y down, z forward) in the robot frame
  // (x forward, y left, z up): the convention of mrpt::obs::CObservationStereoImages::cameraPose.
  mrpt::poses::CPose3D pose_on_robot = opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);

  // Z = f B / d (paper section 3.2). d must be > 0.
  double depthForDisparity(double disparity) const {
    return reference.focal_px * baseline_m / disparity;
  }
  double disparityForDepth(double depth_m) const {
    return reference.focal_px * baseline_m / depth_m;
  }

  // The reference camera's ray through image point (x, y), in the robot frame's axes, per unit of
  // depth along the optical axis: the robot-frame offset from the camera of the point seen
  // there at depth Z is Z times this.
  mrpt::math::TVector3D rayOnRobot(double x, double y) const;
  // Where that ray meets the floor (z = 0), robot frame; nullopt if it never does (level or
  // looking up, or a camera at or below the floor).
  std::optional<mrpt::math::TPoint2D> floorPointOnRobot(double x, double y) const;
  // Where what image point (x, y) reads at disparity d lies, robot frame, dropped onto the floor
  // plane (x ahead, y to the left).
  mrpt::math::TPoint2D readingOnRobot(double x, double y, double disparity) const;

  // The optical-frame pose of a camera mounted at (x, y, z) on the robot, turned left by `yaw`
  // and pitched down by `tilt_down` (radians), as a person measures it on the robot.
  static mrpt::poses::CPose3D opticalPoseOnRobot(double x, double y, double z, double yaw,
                                                 double tilt_down);
};

// Loads the rig from an ini section. Keys (all optional, defaults as above):
//   width, height, focal_px, cx, cy, baseline_m,
//   secondary_cameras  "bx by; bx by; ..." e.g. "-1 0; 0 -1"
//   mount_x, mount_y, mount_z (metres), mount_yaw_deg, mount_tilt_deg (down is positive)
CameraRig loadCameraRig(IniSection& section);

// What makes a rig from elsewhere (a rawlog's calibration) unusable, "" if nothing: the ranges
// loadCameraRig enforces (image size, focal length, principal point, baseline, secondaries,
// a finite mount pose), so that every size and offset derived from it stays bounded.
std::string implausibleRig(const CameraRig& rig);

// Parses "bx by; bx by; ..."; throws ConfigError naming `what` on malformed text.
std::vector<SecondaryCamera> parseSecondaryCameras(const std::string& text, const std::string& what);

}  // namespace stereonav
