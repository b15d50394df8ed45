#include "observations/camera_rig_merge.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

#include "observations/rawlog_reader.h"
#include "observations/rawlog_writer.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& warning : warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(CameraRigMergeTest, OneSourceIsTakenAsItIs) {
  const CameraRig ini = triclopsRig();
  CameraRig observed = binocularRig();
  observed.baseline_m = 0.12;
  const auto from_ini = mergeCameraRigs(ini, std::nullopt, {});
  expectSameRig(ini, from_ini.rig);
  EXPECT_TRUE(from_ini.warnings.empty());
  const auto from_rawlog = mergeCameraRigs(std::nullopt, observed, {});
  expectSameRig(observed, from_rawlog.rig);
  EXPECT_TRUE(from_rawlog.warnings.empty());
  EXPECT_THROW(mergeCameraRigs(std::nullopt, std::nullopt, {}), std::invalid_argument);
}

TEST(CameraRigMergeTest, AgreementWithinToleranceIsSilent) {
  const CameraRig ini = triclopsRig();
  CameraRig observed = ini;
  observed.reference.focal_px += 0.3;  // tolerance 0.5 px
  observed.reference.cx -= 0.4;        // tolerance 0.5 px
  observed.baseline_m += 0.0005;       // tolerance 1 mm
  observed.pose_on_robot = observed.pose_on_robot + mrpt::poses::CPose3D(0.005, 0, 0, 0, 0, 0);
  const auto merged = mergeCameraRigs(ini, observed, {});
  EXPECT_TRUE(merged.warnings.empty()) << merged.warnings[0];
  expectSameRig(ini, merged.rig);
}

TEST(CameraRigMergeTest, IniWinsAndEachMismatchIsReported) {
  const CameraRig ini = triclopsRig();
  CameraRig observed = ini;
  observed.reference.focal_px = 52.0;  // ini 50
  observed.reference.cy = 30.0;        // ini 23.5
  observed.baseline_m = 0.12;          // ini 0.1: also moves the secondary cameras 2 cm
  observed.pose_on_robot = CameraRig::opticalPoseOnRobot(0.25, 0.05, 0.8, mrpt::DEG2RAD(5.0),
                                                         mrpt::DEG2RAD(13.0));  // ini 0.2, 10 deg
  const auto merged = mergeCameraRigs(ini, observed, {});
  expectSameRig(ini, merged.rig);
  EXPECT_TRUE(mentions(merged.warnings, "focal length: ini 50 px, rawlog 52 px"));
  EXPECT_TRUE(mentions(merged.warnings, "principal point y: ini 23.5 px, rawlog 30 px"));
  EXPECT_FALSE(mentions(merged.warnings, "principal point x"));
  EXPECT_TRUE(mentions(merged.warnings, "baseline: ini 0.1 m, rawlog 0.12 m"));
  EXPECT_TRUE(mentions(merged.warnings, "secondary camera 0 offset x"));  // 0.10 vs 0.12 m
  EXPECT_TRUE(mentions(merged.warnings, "secondary camera 1 offset y"));
  EXPECT_TRUE(mentions(merged.warnings, "camera position on the robot"));
  EXPECT_TRUE(
      mentions(merged.warnings, "camera orientation on the robot: ini and rawlog differ by 3"));
  EXPECT_EQ(merged.warnings.size(), 7u);
  for (const auto& warning : merged.warnings) {
    EXPECT_NE(warning.find("using the ini value"), std::string::npos) << warning;
  }
}

TEST(CameraRigMergeTest, DifferentCamerasAreReported) {
  const auto merged = mergeCameraRigs(triclopsRig(), binocularRig(), {});
  EXPECT_TRUE(mentions(merged.warnings, "secondary cameras: ini has 2, rawlog 1"));
  CameraRig small = triclopsRig();
  small.reference.width = 32;
  EXPECT_TRUE(mentions(mergeCameraRigs(triclopsRig(), small, {}).warnings,
                       "image size: ini 64x48, rawlog 32x48"));
}

TEST(CameraRigMergeTest, IniRigAgainstARecordedRawlog) {
  // The whole path a mapper takes: [rig] from the ini, the rig recorded with the first frame.
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("recorded.rawlog");
  {
    RawlogWriter writer(path, {});
    writer.write(sampleFrames(triclopsRig(), 1)[0]);
  }
  RawlogReader reader(path, {});
  const auto frame = reader.next();
  ASSERT_TRUE(frame.has_value());

  // The same head as triclopsRig() but for the focal length.
  mrpt::config::CConfigFileMemory config(
      "[rig]\nwidth = 64\nheight = 48\nfocal_px = 52\ncx = 31.5\ncy = 23.5\nbaseline_m = 0.1\n"
      "secondary_cameras = -1 0; 0 -1\nmount_x = 0.2\nmount_y = 0.05\nmount_z = 0.8\n"
      "mount_yaw_deg = 5\nmount_tilt_deg = 10\n");
  IniSection section(config, "rig");
  const auto merged = mergeCameraRigs(loadCameraRig(section), frame->rig, {});
  ASSERT_EQ(merged.warnings.size(), 1u);
  EXPECT_EQ(merged.warnings[0],
            "focal length: ini 52 px, rawlog 50 px (differ by more than 0.5 px); using the ini value");
  EXPECT_DOUBLE_EQ(merged.rig.reference.focal_px, 52.0);
}

TEST(CameraRigMergeTest, TolerancesLoadFromIni) {
  mrpt::config::CConfigFileMemory config(
      "[rawlog]\ntolerance_focal_px = 3\ntolerance_angle_deg = 5\n[bad]\ntolerance_baseline_m = "
      "-1\n");
  IniSection section(config, "rawlog");
  const CalibrationTolerance tolerance = loadCalibrationTolerance(section);
  section.rejectUnknownKeys();
  EXPECT_DOUBLE_EQ(tolerance.focal_px, 3.0);
  EXPECT_DOUBLE_EQ(tolerance.angle_deg, 5.0);
  EXPECT_DOUBLE_EQ(tolerance.position_m, CalibrationTolerance{}.position_m);
  IniSection bad(config, "bad");
  EXPECT_THROW(loadCalibrationTolerance(bad), ConfigError);
}

}  // namespace
}  // namespace stereonav
