#include "sensor_model/sensor_model_options.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace stereonav {
namespace {

TEST(SensorModelOptionsTest, LoadsKeysAndRejectsBadValues) {
  mrpt::config::CConfigFileMemory ini(
      "[grid]\nmax_range_m = 12.5\nclear_invalid_columns_to_m = 3\n"
      "[bad]\nmax_range_m = 0\n");
  IniSection grid(ini, "grid");
  const SensorModelOptions options = loadSensorModelOptions(grid);
  EXPECT_DOUBLE_EQ(options.max_range_m, 12.5);
  EXPECT_DOUBLE_EQ(options.clear_invalid_columns_to_m, 3.0);
  IniSection bad(ini, "bad");
  try {
    loadSensorModelOptions(bad);
    FAIL() << "max_range_m = 0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[bad] max_range_m"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stereonav
