#include "explorer/explorer_options.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/options_loading.h"

namespace stereonav {
namespace {

using test_support::configErrorOf;
using test_support::loadSectionText;

ExplorerOptions load(const std::string& body) { return loadSectionText("explorer", body, loadExplorerOptions); }

TEST(ExplorerOptionsTest, TheTunablesOfTheExplorersPartsAreReadFromTheIni) {
  const ExplorerOptions options = load(
      "guard_horizon_m = 3\nstop_gap_m = 0.4\nscan_memory_s = 0.5\nheld_speed_mps = 0.1\nholding_depth_m = 0.2\n"
      "blocked_command_mps = 0.2\nblocked_speed_mps = 0.03\nblocked_s = 2\nback_off_speed_mps = 0.3\n"
      "back_off_s = 1\nfacing_tolerance_deg = 10\nmin_turn_rate = 0.3\nturn_braking = 2\n"
      "look_around_spacing_m = 1.5\nescape_speed_mps = 0.25\nresolving_views = 8\nlook_hold_s = 2\n"
      "arrived_m = 0.5\nprogress_m = 0.2\nvisit_spacing_m = 0.2\nescape_search_m = 2\nfailed_escape_m = 0.4\n"
      "speck_cells = 3\nlook_from_afar_m = 1.5\nrecovery_restarts = 1\nrecovery_restart_spacing_s = 12\n");
  EXPECT_EQ(options.guard_horizon_m, 3.0);
  EXPECT_EQ(options.stop_gap_m, 0.4);
  EXPECT_EQ(options.scan_memory_s, 0.5);
  EXPECT_EQ(options.held_speed_mps, 0.1);
  EXPECT_EQ(options.holding_depth_m, 0.2);
  EXPECT_EQ(options.blocked_command_mps, 0.2);
  EXPECT_EQ(options.blocked_speed_mps, 0.03);
  EXPECT_EQ(options.blocked_s, 2.0);
  EXPECT_EQ(options.back_off_speed_mps, 0.3);
  EXPECT_EQ(options.back_off_s, 1.0);
  EXPECT_NEAR(options.facing_tolerance_rad, 10.0 * M_PI / 180.0, 1e-12);
  EXPECT_EQ(options.min_turn_rate, 0.3);
  EXPECT_EQ(options.turn_braking, 2.0);
  EXPECT_EQ(options.look_around_spacing_m, 1.5);
  EXPECT_EQ(options.escape_speed_mps, 0.25);
  EXPECT_EQ(options.resolving_views, 8);
  EXPECT_EQ(options.look_hold_s, 2.0);
  EXPECT_EQ(options.arrived_m, 0.5);
  EXPECT_EQ(options.progress_m, 0.2);
  EXPECT_EQ(options.visit_spacing_m, 0.2);
  EXPECT_EQ(options.escape_search_m, 2.0);
  EXPECT_EQ(options.failed_escape_m, 0.4);
  EXPECT_EQ(options.speck_cells, 3);
  EXPECT_EQ(options.look_from_afar_m, 1.5);
  EXPECT_EQ(options.recovery_restarts, 1);
  EXPECT_EQ(options.recovery_restart_spacing_s, 12.0);
}

TEST(ExplorerOptionsTest, WithoutTheKeysTheDefaultsAreExactlyTheStructs) {
  const ExplorerOptions loaded = load("");
  const ExplorerOptions defaults;
  EXPECT_EQ(loaded.facing_tolerance_rad, defaults.facing_tolerance_rad);
  EXPECT_EQ(loaded.turn_in_place_rad, defaults.turn_in_place_rad);
  EXPECT_EQ(loaded.resolving_views, defaults.resolving_views);
  EXPECT_EQ(loaded.guard_horizon_m, defaults.guard_horizon_m);
}

TEST(ExplorerOptionsTest, OutOfRangeValuesNameTheKey) {
  EXPECT_NE(configErrorOf([] { load("resolving_views = 0\n"); }).find("resolving_views"), std::string::npos);
  EXPECT_NE(configErrorOf([] { load("speck_cells = -1\n"); }).find("speck_cells"), std::string::npos);
  EXPECT_NE(configErrorOf([] { load("recovery_restarts = -1\n"); }).find("recovery_restarts"), std::string::npos);
  EXPECT_NE(configErrorOf([] { load("look_from_afar_m = -1\n"); }).find("look_from_afar_m"), std::string::npos);
  EXPECT_NE(configErrorOf([] { load("facing_tolerance_deg = 120\n"); }).find("facing_tolerance_deg"),
            std::string::npos);
  EXPECT_NE(configErrorOf([] { load("stop_gap_m = -0.1\n"); }).find("stop_gap_m"), std::string::npos);
  EXPECT_NE(configErrorOf([] { load("blocked_s = 0\n"); }).find("blocked_s"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
