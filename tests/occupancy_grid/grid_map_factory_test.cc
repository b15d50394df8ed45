#include "occupancy_grid/grid_map_factory.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "test_scans.h"

namespace stereonav {
namespace {

GridMapOptions load(const std::string& text) {
  mrpt::config::CConfigFileMemory ini(text);
  IniSection section(ini, "grid");
  return loadGridMapOptions(section);
}

// One obstacle seen by both sensors: d = 1.5 on the unit camera puts it 2..4 m ahead (paper
// eq. 1); the virtual laser, under the camera, sees it straight ahead at 3 m.
mrpt::obs::CSensoryFrame frameWithBothObservations() {
  auto disparity = CObservationDisparityScan::Create();
  disparity->scan = testing::scanOf({1.5f});
  disparity->camera = testing::unitCamera();
  auto laser = mrpt::obs::CObservation2DRangeScan::Create();
  laser->aperture = 0.0f;
  laser->maxRange = 10.0f;
  laser->resizeScanAndAssign(1, 3.0f, true);
  mrpt::obs::CSensoryFrame frame;
  frame.insert(disparity);
  frame.insert(laser);
  return frame;
}

TEST(GridMapFactoryTest, LoadsTheWholeGridSection) {
  const GridMapOptions options = load(
      "[grid]\nmodel = linear\nresolution = 0.1\nmin_x = -4\nupdate_step = 15\n"
      "free_below = 40\noccupied_above = 160\naccuracy_preservation = false\n"
      "free_preservation_range_m = 1.5\nclear_invalid_columns_to_m = 2.5\n");
  EXPECT_EQ(options.model, GridModel::kLinear);
  EXPECT_EQ(options.stereo.limits.resolution, 0.1);
  EXPECT_EQ(options.stereo.limits.min_x, -4.0);
  EXPECT_EQ(options.stereo.update.update_step, 15);
  EXPECT_EQ(options.stereo.update.scale.free_below, 40);
  EXPECT_EQ(options.stereo.update.scale.occupied_above, 160);
  EXPECT_FALSE(options.stereo.update.accuracy_preservation);
  EXPECT_EQ(options.stereo.update.free_preservation_range_m, 1.5);
  EXPECT_EQ(options.stereo.sensor_model.clear_invalid_columns_to_m, 2.5);
}

TEST(GridMapFactoryTest, BadValuesAndUnknownKeysAreOneLineErrorsNamingTheKey) {
  const auto message = [](const std::string& text) {
    try {
      load(text);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("[grid]\nmodel = bayes\n").find("[grid] model"), std::string::npos);
  EXPECT_NE(message("[grid]\nupdate_stp = 3\n").find("update_stp"), std::string::npos);
  EXPECT_NE(message("[grid]\ng_max = 300\n").find("[grid] g_max"), std::string::npos);
  EXPECT_NE(message("[grid]\noccupied_above = 100\n").find("[grid] occupied_above"),
            std::string::npos);
  EXPECT_NE(message("[grid]\nresolution = 0\n").find("[grid] resolution"), std::string::npos);
  EXPECT_NE(message("[grid]\nmax_x = -20\n").find("[grid] max_x"), std::string::npos);
  EXPECT_NE(message("[grid]\nfree_preservation_range_m = -1\n").find(
                "[grid] free_preservation_range_m"),
            std::string::npos);
}

TEST(GridMapFactoryTest, EitherModelTakesTheSameSensoryFrame) {
  const mrpt::obs::CSensoryFrame frame = frameWithBothObservations();
  const mrpt::poses::CPose3D robot(testing::robotAt(0, 0));

  const auto linear = createGridMap(load("[grid]\nmodel = linear\nresolution = 1\n"));
  const auto* stereo = dynamic_cast<const CStereoOccupancyGridMap*>(linear.get());
  ASSERT_NE(stereo, nullptr);
  EXPECT_TRUE(frame.insertObservationsInto(*linear, robot));
  EXPECT_EQ(testing::occupancyAt(stereo->grid(), 3, 0), 148);

  const auto bayes = createGridMap(
      load("[grid]\nmodel = mrpt_bayes\nresolution = 0.5\nmax_range_m = 9\n"));
  const auto* mrpt_grid = dynamic_cast<const mrpt::maps::COccupancyGridMap2D*>(bayes.get());
  ASSERT_NE(mrpt_grid, nullptr);
  EXPECT_EQ(mrpt_grid->getResolution(), 0.5f);
  EXPECT_EQ(mrpt_grid->insertionOptions.maxDistanceInsertion, 9.0f);
  EXPECT_TRUE(frame.insertObservationsInto(*bayes, robot));
  // The ray ends 3 m ahead of the robot at (0.5, 0.5): occupied there, free on the way.
  EXPECT_LT(mrpt_grid->getPos(3.55, 0.55), 0.5f);
  EXPECT_GT(mrpt_grid->getPos(1.75, 0.55), 0.5f);
}

}  // namespace
}  // namespace stereonav
