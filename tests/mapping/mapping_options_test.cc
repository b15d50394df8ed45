#include "mapping/mapping_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>

#include "support/options_loading.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

MappingOptions load(const std::string& text) {
  return loadMappingOptions(mrpt::config::CConfigFileMemory(text));
}

std::string errorOf(const std::string& text) {
  return test_support::configErrorOf([&] { load(text); });
}

TEST(MappingOptionsTest, EachSectionGoesToItsStage) {
  const MappingOptions options = load(
      "[rig]\nwidth = 160\nheight = 120\nfocal_px = 80\ncx = 79.5\ncy = 59.5\n"
      "[rawlog]\nsensor_label = HEAD\ntolerance_focal_px = 2\n"
      "[stereo]\nmax_disparity = 15\nwindow = 9\n"
      "[spike_removal]\nmin_region_pixels = 20\n"
      "[projection]\nrobot_height_m = 1.5\n"
      "[grid]\nmodel = mrpt_bayes\nresolution = 0.1\n"
      "[mapping]\npanel_range_m = 3\nvirtual_scans = true\n");
  ASSERT_TRUE(options.rig.has_value());
  EXPECT_EQ(options.rig->reference.width, 160);
  EXPECT_EQ(options.sensor_label, "HEAD");
  EXPECT_EQ(options.calibration_tolerance.focal_px, 2.0);
  EXPECT_EQ(options.stereo.max_disparity, 15);
  // The localizer's wall segments count a scan's readings as sharing their errors over the window.
  EXPECT_EQ(options.localization.walls.segments.correlated_readings, 9);
  EXPECT_EQ(options.spike_removal.segmentation.min_region_pixels, 20);
  EXPECT_EQ(options.projection.robot_height_m, 1.5);
  EXPECT_EQ(options.grid.model, GridModel::kMrptBayes);
  EXPECT_EQ(options.grid.stereo.limits.resolution, 0.1);
  EXPECT_EQ(options.mapper.panel_range_m, 3.0);
  EXPECT_TRUE(options.mapper.virtual_scans);
}

TEST(MappingOptionsTest, AbsentSectionsKeepDefaultsAndNoRigMeansTheRawlogsRig) {
  const MappingOptions options = load("");
  EXPECT_FALSE(options.rig.has_value());
  EXPECT_EQ(options.sensor_label, "");  // follow the first stereo pair
  EXPECT_EQ(options.stereo.max_disparity, StereoOptions{}.max_disparity);
  EXPECT_EQ(options.grid.model, GridModel::kLinear);
}

TEST(MappingOptionsTest, UnknownKeysAreRejectedInEverySection) {
  for (const char* section : {"rig", "rawlog", "stereo", "spike_removal", "projection", "grid", "mapping"}) {
    const std::string message = errorOf(std::string("[") + section + "]\nno_such_key = 1\n");
    EXPECT_NE(message.find(std::string("[") + section + "]"), std::string::npos) << message;
    EXPECT_NE(message.find("no_such_key"), std::string::npos) << message;
  }
  EXPECT_NE(errorOf("[mapping]\npanel_range_m = 0\n").find("panel_range_m"), std::string::npos);
}

TEST(MappingOptionsTest, RawlogSectionNamesSeparateCamerasAndACalibrationFile) {
  const test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("calibration.yaml");
  std::ofstream(path) << "%YAML:1.0\nM1: [400, 0, 320, 0, 400, 240, 0, 0, 1]\nD1: [-0.1, 0, 0, 0]\n"
                         "M2: [400, 0, 320, 0, 400, 240, 0, 0, 1]\nD2: [0, 0, 0, 0]\n"
                         "R: [1, 0, 0, 0, 1, 0, 0, 0, 1]\nT: [-0.12, 0, 0]\n";
  const MappingOptions options =
      load("[rawlog]\ncamera_labels = LEFT RIGHT\npairing_tolerance_s = 0.01\ncalibration = " + path + "\n");
  EXPECT_EQ(options.pairing.labels, (std::vector<std::string>{"LEFT", "RIGHT"}));
  EXPECT_DOUBLE_EQ(options.pairing.max_time_difference_s, 0.01);
  ASSERT_TRUE(options.calibration.has_value());
  EXPECT_DOUBLE_EQ(options.calibration->cameras[1].centreInReference()[0], 0.12);
  EXPECT_DOUBLE_EQ(options.calibration->cameras[0].distortion[0], -0.1);
  const std::string missing = errorOf("[rawlog]\ncalibration = /nonexistent/calib.yaml\n");
  EXPECT_NE(missing.find("[rawlog] calibration: /nonexistent/calib.yaml: cannot read"), std::string::npos)
      << missing;
}

TEST(MappingOptionsTest, FileErrorsNameTheFile) {
  EXPECT_THROW(loadMappingOptionsFile("/nonexistent/map.ini"), std::runtime_error);
  const test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("mapping.ini");
  std::ofstream(path) << "[stereo]\nwindwo = 7\n";
  try {
    loadMappingOptionsFile(path);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": [stereo] ", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace stereonav
