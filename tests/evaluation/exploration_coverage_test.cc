#include "evaluation/exploration_coverage.h"

#include <gtest/gtest.h>

#include <string>

#include "../simulator/world_text.h"
#include "../explorer/test_grids.h"

namespace stereonav {
namespace {

// The ground truth of a world given as ini text, at 0.1 m, without a margin.
GroundTruthMap truthAtTenCentimetres(const std::string& world_text) {
  GroundTruthMapOptions options;
  options.resolution_m = 0.1;
  options.margin_m = 0.0;
  return GroundTruthMap(worldFromText(world_text), options);
}

TEST(ExplorationCoverageTest, CountsTrueFreeCellsTheMapCallsFreeAndThoseItHasSeenAtAll) {
  // A 2 m x 2 m world at 0.1 m with a 0.4 m x 0.4 m box in the middle (cells 8..11 both ways). A
  // body of radius 0.25 m has its centre at least 2.5 cells from any obstacle cell's centre (the
  // border counts as one), so from the third cell in, and sweeps cell centres up to 2.5 cells away:
  // every free cell but the world's four corners (2.8 cells from the nearest place for the centre),
  // 400 - 16 - 4. (With a radius of a whole number of cells a cell's centre lies exactly on the
  // body's edge and rounding decides.)
  const GroundTruthMap truth =
      truthAtTenCentimetres("[world]\nbounds = 0 0 2 2\n[box.b]\ncenter = 1 1\nsize = 0.4 0.4\n");
  TestGrid map(20, 20);
  // The west half mapped free (the box's cells there too: they are not free space, so they do
  // not count), the next five columns mapped occupied, wrongly but for the box's cells.
  // Reachable and mapped free: 200 cells less 8 of the box and 2 corners; mapped occupied: 100
  // cells less 8 of the box.
  map.free(0, 0, 9, 19).occupied(10, 0, 14, 19);
  const ExplorationCoverage coverage = ReachableFloor(truth, 0.25, 0.5, 0.5).measure(map.grid());
  EXPECT_NEAR(coverage.reachable_free_m2, 380 * 0.01, 1e-9);
  EXPECT_NEAR(coverage.covered_m2, 190 * 0.01, 1e-9);
  EXPECT_NEAR(coverage.seen_m2, (190 + 92) * 0.01, 1e-9);
  EXPECT_NEAR(coverage.coverage, 190.0 / 380.0, 1e-9);
  EXPECT_NEAR(coverage.seen_coverage, 282.0 / 380.0, 1e-9);
  EXPECT_NEAR(coverage.free_area_m2, 2.0, 1e-9);
  EXPECT_NEAR(coverage.known_area_m2, 3.0, 1e-9);
}

TEST(ExplorationCoverageTest, FloorTheBodyCannotReachDoesNotCount) {
  // A wall at x 1.45 .. 1.55 fills cells 14 and 15 and leaves a strip of 4 cells east of it, too
  // narrow for a body 0.5 m across: only the 14 columns west of the wall are reachable, less
  // their four corners.
  const GroundTruthMap truth = truthAtTenCentimetres("[world]\nbounds = 0 0 2 2\n[wall.w]\npoints = 1.5 0; 1.5 2\n");
  TestGrid map(20, 20);
  map.free(0, 0, 19, 19);
  const ExplorationCoverage coverage = ReachableFloor(truth, 0.25, 0.5, 0.5).measure(map.grid());
  EXPECT_NEAR(coverage.reachable_free_m2, (14 * 20 - 4) * 0.01, 1e-9);
  EXPECT_NEAR(coverage.coverage, 1.0, 1e-9);
  // Started inside the wall: nothing is reachable.
  EXPECT_EQ(ReachableFloor(truth, 0.25, 1.5, 1.0).measure(map.grid()).reachable_free_m2, 0.0);
}

}  // namespace
}  // namespace stereonav
