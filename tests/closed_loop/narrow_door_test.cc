// A door 0.8 m wide for a body 0.6 m wide, the narrowest of issue 18's doors: 0.1 m each side,
// no more than the guard's margin (ExplorerOptions::pass_beside_speed_mps). The world is the shipped
// ini/worlds/door_080.ini, explored with the shipped 320x240 config on true poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "closed_loop/exploration_run.h"
#include "mapping/rawlog_mapping.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

const std::string kRepository = std::string(STEREONAV_TEST_DATA_DIR) + "/../..";

TEST(NarrowDoorTest, TheExplorerDrivesThroughADoorOnlyATenthOfAMetreWiderEachSideThanItsBody) {
  const World world = loadWorld(kRepository + "/ini/worlds/door_080.ini");
  const ExplorationConfig config = loadExplorationConfig(kRepository + "/ini/explore_320x240.ini");
  const std::string directory = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/closed_loop/door_080";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  ExplorationJob job;
  job.output_prefix = directory + "/door";
  job.max_time_s = 300.0;
  const ExplorationReport report = runExploration(world, config, job);

  EXPECT_EQ(report.collisions, 0) << report.summary();
  // Room B lies east of the partition at x = 3 (its face at 3.05); its body centre 0.3 m past that
  // face means the whole body went through.
  double farthest_east = -1e9;
  for (const mrpt::poses::CPose2D& pose : loadPoseList(job.output_prefix + ".truth.txt")) {
    farthest_east = std::max(farthest_east, pose.x());
  }
  EXPECT_GT(farthest_east, 3.35) << report.summary();
  // Room B is 18 of the 27 m2 of floor (less what the body cannot sweep): it was explored, not
  // only entered. Before the guard let the body pass within its margin, the robot held at the
  // door and ended at 46%.
  EXPECT_GE(report.coverage.coverage, 0.9) << report.summary();
}

}  // namespace
}  // namespace stereonav
