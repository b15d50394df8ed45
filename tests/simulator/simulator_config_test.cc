#include "simulator/simulator_config.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include "support/options_loading.h"

namespace stereonav {
namespace {

TEST(SimulatorConfig, ReadsEverySimulatorSectionAndGivesTheTrueMapTheRobotsHeightBand) {
  const mrpt::config::CConfigFileMemory file(
      "[rig]\nwidth = 64\nheight = 48\nfocal_px = 32\n"
      "[sim_sensor]\nnoise_sigma = 0.5\nseed = 7\n"
      "[sim_robot]\nradius_m = 0.25\nheight_m = 1.4\n"
      "[simulation]\nframe_rate_hz = 4\ncontrol_rate_hz = 40\n"
      "[rawlog]\ncompression_level = 0\n"
      "[ground_truth_map]\nresolution_m = 0.02\n");
  const SimulatorConfig config = loadSimulatorConfig(file, "run.ini");
  EXPECT_EQ(config.rig.reference.width, 64);
  EXPECT_EQ(config.rig.reference.height, 48);
  EXPECT_DOUBLE_EQ(config.sensor.noise_sigma, 0.5);
  EXPECT_EQ(config.sensor.seed, 7);
  EXPECT_DOUBLE_EQ(config.robot.radius_m, 0.25);
  EXPECT_DOUBLE_EQ(config.simulation.frame_rate_hz, 4.0);
  EXPECT_DOUBLE_EQ(config.simulation.control_rate_hz, 40.0);
  EXPECT_EQ(config.rawlog.compression_level, 0);
  EXPECT_DOUBLE_EQ(config.ground_truth.resolution_m, 0.02);
  EXPECT_DOUBLE_EQ(config.ground_truth.band_min_z, 0.0);
  EXPECT_DOUBLE_EQ(config.ground_truth.band_max_z, 1.4);
}

TEST(SimulatorConfig, AnUnknownKeyIsAnErrorNamingTheFileSectionAndKey) {
  const mrpt::config::CConfigFileMemory file("[sim_robot]\nradius = 0.3\n");
  const std::string message = test_support::configErrorOf([&] { loadSimulatorConfig(file, "run.ini"); });
  EXPECT_NE(message.find("run.ini"), std::string::npos) << message;
  EXPECT_NE(message.find("[sim_robot]"), std::string::npos) << message;
  EXPECT_NE(message.find("radius"), std::string::npos) << message;
}

}  // namespace
}  // namespace stereonav
