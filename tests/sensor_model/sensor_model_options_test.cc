#include "sensor_model/sensor_model_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace stereonav {
namespace {

TEST(SensorModelOptionsTest, LoadsKeysAndRejectsBadValues) {
  mrpt::config::CConfigFileMemory ini(
      "[grid]\nmax_range_m = 12.5\nclear_invalid_columns_to_m = 3\n"
      "disparity_uncertainty_px = 0.3\nkeep_obstacle_borders = true\n"
      "[bad]\nmax_range_m = 0\n"
      "[bad_uncertainty]\ndisparity_uncertainty_px = 0\n");
  IniSection grid(ini, "grid");
  const SensorModelOptions options = loadSensorModelOptions(grid);
  EXPECT_DOUBLE_EQ(options.max_range_m, 12.5);
  EXPECT_DOUBLE_EQ(options.clear_invalid_columns_to_m, 3.0);
  EXPECT_DOUBLE_EQ(options.disparity_uncertainty_px, 0.3);
  EXPECT_TRUE(options.keep_obstacle_borders);
  IniSection bad(ini, "bad");
  try {
    loadSensorModelOptions(bad);
    FAIL() << "max_range_m = 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[bad] max_range_m"), std::string::npos) << e.what();
  }
  IniSection bad_uncertainty(ini, "bad_uncertainty");
  try {
    loadSensorModelOptions(bad_uncertainty);
    FAIL() << "disparity_uncertainty_px = 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "[bad_uncertainty] disparity_uncertainty_px: must be positive (at most 1000), got '0'");
  }
}

TEST(SensorModelOptionsTest, DefaultsAreThePapers) {
  mrpt::config::CConfigFileMemory ini("[grid]\n");
  IniSection grid(ini, "grid");
  const SensorModelOptions options = loadSensorModelOptions(grid);
  EXPECT_DOUBLE_EQ(options.disparity_uncertainty_px, 0.5);  // equation 1
  EXPECT_FALSE(options.keep_obstacle_borders);
}

}  // namespace
}  // namespace stereonav
