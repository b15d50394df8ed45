#include "column_projection/projection_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <string>

namespace stereonav {
namespace {

TEST(ProjectionOptionsTest, LoadsEveryKey) {
  mrpt::config::CConfigFileMemory config(
      "[projection]\nfloor_clearance_m = 0.1\nrobot_height_m = 1.4\nsurface_band_px = 1.5\n"
      "surface_band_scan_only = true\nmax_depth_m = 3\nfloor_end_max_depth_m = 2.5\nfloor_end_clear_max_depth_m = 3.5\nnear_floor_m = 0.4\n"
      "scan_max_range_m = 6\n");
  IniSection section(config, "projection");
  const ProjectionOptions options = loadProjectionOptions(section);
  section.rejectUnknownKeys();
  EXPECT_DOUBLE_EQ(options.floor_clearance_m, 0.1);
  EXPECT_DOUBLE_EQ(options.robot_height_m, 1.4);
  EXPECT_DOUBLE_EQ(options.surface_band_px, 1.5);
  EXPECT_TRUE(options.surface_band_scan_only);
  EXPECT_DOUBLE_EQ(options.max_depth_m, 3.0);
  EXPECT_DOUBLE_EQ(options.floor_end_max_depth_m, 2.5);
  EXPECT_DOUBLE_EQ(options.floor_end_clear_max_depth_m, 3.5);
  EXPECT_DOUBLE_EQ(options.near_floor_m, 0.4);
  EXPECT_DOUBLE_EQ(options.scan_max_range_m, 6.0);
}

// A depth limit that is off (0) when its key is absent and rejects a negative value.
void expectOffByDefaultAndNotNegative(const std::string& key, double ProjectionOptions::*member) {
  SCOPED_TRACE(key);
  mrpt::config::CConfigFileMemory defaults("[projection]\n");
  IniSection default_section(defaults, "projection");
  EXPECT_EQ(loadProjectionOptions(default_section).*member, 0.0);
  mrpt::config::CConfigFileMemory config("[projection]\n" + key + " = -1\n");
  IniSection section(config, "projection");
  EXPECT_THROW(loadProjectionOptions(section), ConfigError);
}

TEST(ProjectionOptionsTest, DepthLimitsAreOffByDefaultAndNotNegative) {
  expectOffByDefaultAndNotNegative("max_depth_m", &ProjectionOptions::max_depth_m);
  expectOffByDefaultAndNotNegative("floor_end_max_depth_m", &ProjectionOptions::floor_end_max_depth_m);
  expectOffByDefaultAndNotNegative("floor_end_clear_max_depth_m",
                                   &ProjectionOptions::floor_end_clear_max_depth_m);
  expectOffByDefaultAndNotNegative("near_floor_m", &ProjectionOptions::near_floor_m);
}

TEST(ProjectionOptionsTest, SurfaceBandIsOffByDefaultAndNotNegative) {
  mrpt::config::CConfigFileMemory defaults("[projection]\n");
  IniSection default_section(defaults, "projection");
  EXPECT_EQ(loadProjectionOptions(default_section).surface_band_px, 0.0);
  mrpt::config::CConfigFileMemory config("[projection]\nsurface_band_px = -0.5\n");
  IniSection section(config, "projection");
  try {
    loadProjectionOptions(section);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[projection] surface_band_px: expected [0, 10000], got '-0.5'");
  }
}

TEST(ProjectionOptionsTest, RobotMustBeTallerThanTheFloorClearance) {
  mrpt::config::CConfigFileMemory config(
      "[projection]\nfloor_clearance_m = 0.5\nrobot_height_m = 0.4\n");
  IniSection section(config, "projection");
  try {
    loadProjectionOptions(section);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_STREQ(error.what(), "[projection] robot_height_m: must be above floor_clearance_m");
  }
}

TEST(ProjectionOptionsTest, MaxRangeMustBePositive) {
  mrpt::config::CConfigFileMemory config("[projection]\nscan_max_range_m = 0\n");
  IniSection section(config, "projection");
  EXPECT_THROW(loadProjectionOptions(section), ConfigError);
}

}  // namespace
}  // namespace stereonav
