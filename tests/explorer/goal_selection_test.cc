#include "explorer/goal_selection.h"

#include <gtest/gtest.h>

#include "test_grids.h"

namespace stereonav {
namespace {

// Defaults: target switch penalty 2 m, pocket penalty 25 m below 3 m2, goals within 0.2 m of the
// body (radius 0.3 + margin 0.1) from a frontier cell.
ExplorerOptions options() { return ExplorerOptions{}; }

// A corridor 10 m long and 1 m wide (x 2 .. 12, y 1.5 .. 2.5, walls along both sides), open at
// both ends to unknown space: one frontier at each end.
struct Corridor {
  Corridor() : cells(140, 40) {
    cells.free(20, 15, 119, 24).occupied(20, 14, 119, 14).occupied(20, 25, 119, 25);
    grid = std::make_unique<NavigationGrid>(cells.grid(), std::vector<mrpt::poses::CPose2D>{}, NavigationGridOptions{});
    frontiers = findFrontiers(*grid, 3);
    memory.anchor(cells.grid().frame());
  }

  // The frontier the path from x (on the corridor's centre line) leads to: "west" or "east".
  std::string chosen(const GoalSelection& selection, double x) const {
    CostToGoOptions planner;
    planner.body_radius_m = 0.4;
    planner.repulsion_weight = 0.0;  // costs are path lengths
    CostToGoField field(*grid, planner);
    field.compute(selection.goals(*grid, field, frontiers, planner.body_radius_m, memory));
    int col = 0, row = 0;
    EXPECT_TRUE(grid->cellAt(x, 2.05, col, row));
    if (!field.reachable(col, row)) return "none";
    return frontiers[static_cast<size_t>(field.label(col, row))].centroid_x < 7.0 ? "west" : "east";
  }
  int index(const std::string& end) const {
    return (frontiers[0].centroid_x < 7.0) == (end == "west") ? 0 : 1;
  }

  TestGrid cells;
  std::unique_ptr<NavigationGrid> grid;
  std::vector<Frontier> frontiers;
  FrontierMemory memory{ExplorerOptions{}};
};

TEST(GoalSelectionTest, PrefersTheNearerFrontier) {
  const Corridor corridor;
  ASSERT_EQ(corridor.frontiers.size(), 2u);
  const GoalSelection selection(options());
  // From x 9.05 the east end is 3 m away, the west end 7 m; from x 4.05, the other way round.
  EXPECT_EQ(corridor.chosen(selection, 9.05), "east");
  EXPECT_EQ(corridor.chosen(selection, 4.05), "west");
}

TEST(GoalSelectionTest, StaysWithItsTargetUnlessAnotherIsTheSwitchPenaltyNearer) {
  const Corridor corridor;
  ASSERT_EQ(corridor.frontiers.size(), 2u);
  GoalSelection selection(options());
  selection.aimAt({2.5, 2.05}, corridor.index("west"));
  // From x 7.55 the east end is about 1.1 m nearer: less than the 2 m penalty on switching.
  EXPECT_EQ(corridor.chosen(selection, 7.55), "west");
  // From x 9.05 it is about 4 m nearer.
  EXPECT_EQ(corridor.chosen(selection, 9.05), "east");
  // Without a target, the nearer end.
  selection.clear();
  EXPECT_EQ(corridor.chosen(selection, 7.55), "east");
}

TEST(GoalSelectionTest, AFrontierOntoASmallPocketWaitsBehindTheRest) {
  Corridor corridor;
  ASSERT_EQ(corridor.frontiers.size(), 2u);
  const GoalSelection selection(options());
  corridor.frontiers[static_cast<size_t>(corridor.index("east"))].unseen_area_m2 = 1.0;
  // The east end is 4 m nearer from x 9.05, but 25 m of penalty sends the robot west.
  EXPECT_EQ(corridor.chosen(selection, 9.05), "west");
}

TEST(GoalSelectionTest, TheTargetCarriesOverToTheFrontierHoldingItsCellsInTheNextMap) {
  const Corridor corridor;
  ASSERT_EQ(corridor.frontiers.size(), 2u);
  GoalSelection selection(options());
  // A target set where no frontier is near now (as after the frontier receded): only its cells,
  // carried over from the previous map, tell which frontier is still the target.
  selection.aimAt({6.0, 2.05}, corridor.index("west"));
  EXPECT_EQ(corridor.chosen(selection, 7.55), "east");
  selection.carryTargetOver(*corridor.grid, corridor.frontiers, corridor.memory);
  EXPECT_EQ(corridor.chosen(selection, 7.55), "west");
}

}  // namespace
}  // namespace stereonav
