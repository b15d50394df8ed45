#include "explorer/goal_selection.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

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


TEST(GoalSelectionTest, TheGoalsAreTheTraversableCellsWithinReachOfAFrontierWhateverTheOrderOfItsCells) {
  // A free room 6 m x 4 m with a pillar in it, 5 cm cells.
  TestGrid cells(140, 100, 0.05);
  cells.free(10, 10, 129, 89).occupied(60, 40, 69, 49);
  const NavigationGrid grid(cells.grid(), std::vector<mrpt::poses::CPose2D>{}, NavigationGridOptions{});
  CostToGoOptions planner;
  planner.body_radius_m = 0.35;
  const CostToGoField field(grid, planner);
  FrontierMemory memory{ExplorerOptions{}};
  memory.anchor(cells.grid().frame());
  // Frontiers drawn by hand, their cells in the orders a finder may give: a winding curve cell
  // by cell (straight and diagonal steps), the same curve backwards with a jump in it, and a
  // scatter overlapping both. The third borders only a pocket, so its goals cost more.
  std::vector<cv::Point> curve;
  for (int col = 20; col <= 50; ++col) curve.emplace_back(col, 30 + (col % 12 < 6 ? col % 12 : 12 - col % 12));
  for (int row = 31; row <= 60; ++row) curve.emplace_back(50 + (row % 3 == 0 ? 1 : 0), row);
  std::vector<cv::Point> backwards(curve.rbegin(), curve.rend());
  for (cv::Point& cell : backwards) cell += cv::Point(45, 5);
  std::swap(backwards[10], backwards[40]);
  const std::vector<cv::Point> scatter{{48, 33}, {90, 70}, {52, 62}, {30, 75}, {91, 71}, {89, 69}};
  std::vector<Frontier> frontiers(3);
  frontiers[0].cells = curve;
  frontiers[1].cells = backwards;
  frontiers[2].cells = scatter;
  for (Frontier& frontier : frontiers) {
    frontier.unseen_area_m2 = 100.0;
    frontier.borders_unknown = true;
  }
  frontiers[2].unseen_area_m2 = 0.5;
  const ExplorerOptions explorer;
  const GoalSelection selection(explorer);
  const std::vector<GoalCell> goals = selection.goals(grid, field, frontiers, planner.body_radius_m, memory);

  // Each traversable cell within goal_distance_m of the body's edge from some frontier cell (its
  // centre within 0.55 m, 11 cells, of that cell's) is a goal once, with the cheapest frontier's
  // seed: the switch penalty, and the pocket penalty on top for the pocket's; among frontiers of
  // one seed the first.
  const double reach_cells = (planner.body_radius_m + explorer.goal_distance_m) / 0.05;
  std::map<std::pair<int, int>, std::pair<double, int>> expected;
  for (int i = 0; i < 3; ++i) {
    const double seed = explorer.target_switch_penalty_m + (i == 2 ? explorer.pocket_penalty_m : 0.0);
    for (const cv::Point& cell : frontiers[static_cast<size_t>(i)].cells) {
      for (int row = 0; row < 100; ++row) {
        for (int col = 0; col < 140; ++col) {
          if (std::hypot(col - cell.x, row - cell.y) > reach_cells + 1e-9 || !field.traversable(col, row)) continue;
          const auto [it, inserted] = expected.try_emplace({col, row}, seed, i);
          if (!inserted && seed < it->second.first) it->second = {seed, i};
        }
      }
    }
  }
  ASSERT_EQ(goals.size(), expected.size());
  std::set<std::pair<int, int>> seen;
  for (const GoalCell& goal : goals) {
    const auto it = expected.find({goal.col, goal.row});
    ASSERT_NE(it, expected.end()) << goal.col << " " << goal.row;
    EXPECT_TRUE(seen.insert({goal.col, goal.row}).second);
    EXPECT_EQ(goal.seed_cost, it->second.first) << goal.col << " " << goal.row;
    EXPECT_EQ(goal.label, it->second.second) << goal.col << " " << goal.row;
  }
}

}  // namespace
}  // namespace stereonav
