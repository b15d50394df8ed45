#include "explorer/cost_to_go_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <utility>

#include "test_grids.h"

namespace stereonav {
namespace {

CostToGoOptions plainOptions(double body_radius) {
  CostToGoOptions options;
  options.body_radius_m = body_radius;
  options.repulsion_distance_m = 0.0;
  options.repulsion_weight = 0.0;
  return options;
}

double pathLength(const std::vector<cv::Point2d>& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i) length += cv::norm(path[i] - path[i - 1]);
  return length;
}

// Distance from a point to the axis-aligned rectangle [x0, x1] x [y0, y1].
double distanceToRect(const cv::Point2d& p, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1});
  const double dy = std::max({y0 - p.y, 0.0, p.y - y1});
  return std::hypot(dx, dy);
}

// 4 m x 4 m of free floor at 0.1 m cells.
TestGrid openFloor() {
  TestGrid cells(40, 40);
  cells.free(0, 0, 39, 39);
  return cells;
}

TEST(CostToGoFieldTest, StraightPathOnOpenFloorHasTheStraightLength) {
  const TestGrid cells = openFloor();
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const auto path = planPath(grid, plainOptions(0.25), 1.05, 2.05, 3.05, 2.05);
  ASSERT_FALSE(path.empty());
  EXPECT_NEAR(pathLength(path), 2.0, 1e-9);
  EXPECT_NEAR(cv::norm(path.front() - cv::Point2d(1.05, 2.05)), 0.0, 1e-9);
  EXPECT_NEAR(cv::norm(path.back() - cv::Point2d(3.05, 2.05)), 0.0, 1e-9);
}

TEST(CostToGoFieldTest, GoesAroundAWallKeepingTheBodyClearOfIt) {
  TestGrid cells = openFloor();
  cells.occupied(20, 0, 20, 29);  // a wall x in [2.0, 2.1], y in [0, 3.0], open above
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const auto path = planPath(grid, plainOptions(0.25), 1.05, 1.05, 3.05, 1.05);
  ASSERT_FALSE(path.empty());
  double highest = 0.0;
  for (const cv::Point2d& p : path) {
    EXPECT_GE(distanceToRect(p, 2.0, 0.0, 2.1, 3.0), 0.25) << p;
    highest = std::max(highest, p.y);
  }
  EXPECT_GE(highest, 3.25);
  // No shorter than the straight legs to the inflated wall end (2.05, 3.25) and back down.
  EXPECT_GE(pathLength(path), 2.0 * std::hypot(1.0, 3.25 - 1.05));
  // No longer than this hand-built grid path (cells whose centres are 0.25 m from the wall, no
  // corner cutting): north 1.4 to (1.05, 2.45), diagonal 7 cells to (1.75, 3.15), north 0.1,
  // east 0.6 over the wall top at y = 3.25 to (2.35, 3.25), and the mirror image down.
  EXPECT_LE(pathLength(path), 2.0 * (1.4 + 0.7 * M_SQRT2 + 0.1) + 0.6 + 1e-9);
}

TEST(CostToGoFieldTest, NeverEntersUnknownCellsAndStaysABodyAwayFromThem) {
  TestGrid cells = openFloor();
  cells.unknown(18, 0, 22, 29);  // unknown band x in [1.8, 2.3], y in [0, 3.0]
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const auto path = planPath(grid, plainOptions(0.25), 1.05, 1.05, 3.05, 1.05);
  ASSERT_FALSE(path.empty());
  for (const cv::Point2d& p : path) EXPECT_GE(distanceToRect(p, 1.8, 0.0, 2.3, 3.0), 0.25) << p;
  // Across the whole floor the band cuts it in two: no path at all.
  cells.unknown(18, 0, 22, 39);
  EXPECT_TRUE(planPath(NavigationGrid(cells.grid(), {}, NavigationGridOptions{}), plainOptions(0.25), 1.05, 1.05, 3.05, 1.05).empty());
}

TEST(CostToGoFieldTest, DoorNarrowerThanTheInflatedBodyIsClosed) {
  TestGrid cells = openFloor();
  // A wall along x = 2.0 .. 2.1 with a door at y in [1.5, 1.5 + width).
  const auto with_door = [&](int cells_wide) {
    TestGrid walled = cells;
    walled.occupied(20, 0, 20, 39).free(20, 15, 20, 15 + cells_wide - 1);
    return walled;
  };
  // The door's middle cell centre must be the body radius from both jambs: 2 r of door (an odd
  // number of cells, the middle centre exactly r from each side) opens it, a cell less does not.
  // 0.35 is the shipped robot's radius with its margin.
  for (const double radius : {0.15, 0.25, 0.35, 0.45}) {
    const int fitting_cells = static_cast<int>(std::lround(2.0 * radius / 0.1));
    const TestGrid narrow = with_door(fitting_cells - 1);
    EXPECT_TRUE(planPath(NavigationGrid(narrow.grid(), {}, NavigationGridOptions{}), plainOptions(radius), 1.05, 1.55,
                         3.05, 1.55)
                    .empty())
        << "radius " << radius;
    const TestGrid wide = with_door(fitting_cells);
    const auto path =
        planPath(NavigationGrid(wide.grid(), {}, NavigationGridOptions{}), plainOptions(radius), 1.05, 1.55, 3.05, 1.55);
    ASSERT_FALSE(path.empty()) << "radius " << radius;
    const double middle = 1.5 + 0.1 * fitting_cells / 2.0;
    for (const cv::Point2d& p : path) {
      if (p.x > 1.9 && p.x < 2.2) {
        EXPECT_NEAR(p.y, middle, 1e-9) << "through the door's middle, radius " << radius;
      }
    }
  }
}

TEST(CostToGoFieldTest, NoPathIntoAClosedRoomOrFromAnUntraversableStart) {
  TestGrid cells = openFloor();
  cells.occupied(25, 25, 35, 35).free(26, 26, 34, 34);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  EXPECT_TRUE(planPath(grid, plainOptions(0.25), 1.05, 1.05, 3.05, 3.05).empty());
  // Start 0.15 m from the grid's edge: the body does not fit there.
  EXPECT_TRUE(planPath(grid, plainOptions(0.25), 0.15, 1.05, 2.05, 1.05).empty());
}

TEST(CostToGoFieldTest, RepulsionKeepsThePathAwayFromAWallItRunsAlong) {
  TestGrid cells(60, 30);
  cells.free(0, 0, 59, 29).occupied(0, 0, 59, 0);  // a wall along y in [0, 0.1]
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  CostToGoOptions repelled = plainOptions(0.25);
  repelled.repulsion_distance_m = 1.0;
  repelled.repulsion_weight = 4.0;
  const auto farthest = [](const std::vector<cv::Point2d>& path) {
    double y = 0.0;
    for (const cv::Point2d& p : path) y = std::max(y, p.y);
    return y;
  };
  const auto plain = planPath(grid, plainOptions(0.25), 0.55, 0.45, 5.45, 0.45);
  const auto with_field = planPath(grid, repelled, 0.55, 0.45, 5.45, 0.45);
  ASSERT_FALSE(plain.empty());
  ASSERT_FALSE(with_field.empty());
  EXPECT_NEAR(farthest(plain), 0.45, 1e-9);  // the shortest path hugs the wall
  EXPECT_GE(farthest(with_field), 0.85);     // the potential field pushes it out
}

TEST(CostToGoFieldTest, EveryCellDescendsToTheCheapestGoalAndInheritsItsLabel) {
  const TestGrid cells = openFloor();
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  CostToGoField field(grid, plainOptions(0.25));
  // Goal 0 at x = 0.55, goal 1 at x = 3.45, both at y = 2.05; goal 1 starts 1 m dearer.
  field.compute({GoalCell{5, 20, 0.0, 0}, GoalCell{34, 20, 1.0, 1}});
  EXPECT_EQ(field.label(10, 20), 0);
  EXPECT_NEAR(field.cost(10, 20), 0.5, 1e-9);
  // Midway is x = 2.0 in distance, but goal 1's extra metre moves the split to x = 2.5.
  EXPECT_EQ(field.label(23, 20), 0);  // x 2.35: 1.8 vs 1.1 + 1
  EXPECT_EQ(field.label(26, 20), 1);  // x 2.65: 2.1 vs 0.8 + 1
  EXPECT_EQ(field.pathFrom(26, 20).back(), cv::Point(34, 20));
}

TEST(CostToGoFieldTest, TiesBreakAsAPriorityQueueOfCostAndCellIndexBreaksThem) {
  // Open floor around a wall, no repulsion (every step weight 1), and goals at equal seed costs
  // placed symmetrically: many cells are reached at equal costs from two sides, and the one
  // that leaves the queue first becomes their parent. The reference is Dijkstra's algorithm on a
  // std::priority_queue of (cost, index) pairs with stale entries skipped.
  TestGrid cells(40, 30);
  cells.free(0, 0, 39, 29).occupied(19, 8, 20, 21);
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  CostToGoField field(grid, plainOptions(0.15));
  const std::vector<GoalCell> goals = {GoalCell{5, 5, 0.0, 0}, GoalCell{34, 5, 0.0, 1}, GoalCell{5, 24, 0.0, 2},
                                       GoalCell{34, 24, 0.0, 3}, GoalCell{12, 15, 0.3, 4}, GoalCell{27, 15, 0.3, 5}};
  field.compute(goals);

  const cv::Rect box = grid.freeCells();
  const auto indexOf = [&](int col, int row) { return (row - box.y) * box.width + col - box.x; };
  std::vector<double> cost(static_cast<size_t>(box.area()), std::numeric_limits<double>::infinity());
  std::vector<int> parent(cost.size(), -1), label(cost.size(), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (const GoalCell& goal : goals) {
    const int index = indexOf(goal.col, goal.row);
    cost[index] = goal.seed_cost;
    parent[index] = index;
    label[index] = goal.label;
    open.push({goal.seed_cost, index});
  }
  const double lengths[2] = {0.1, M_SQRT2 * 0.1};
  int ties = 0;
  while (!open.empty()) {
    const auto [here, index] = open.top();
    open.pop();
    if (here != cost[index]) continue;
    const int col = box.x + index % box.width, row = box.y + index / box.width;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = col + dc, r = row + dr;
        if ((dr == 0 && dc == 0) || !field.traversable(c, r)) continue;
        if (dr != 0 && dc != 0 && (!field.traversable(col + dc, row) || !field.traversable(col, row + dr))) continue;
        const double next = here + lengths[dr != 0 && dc != 0] * 0.5 * (1.0f + 1.0f);
        const int next_index = indexOf(c, r);
        if (next < cost[next_index]) {
          cost[next_index] = next;
          parent[next_index] = index;
          label[next_index] = label[index];
          open.push({next, next_index});
        } else if (next == cost[next_index] && parent[next_index] != index) {
          ++ties;  // reached as cheaply again: the parent is whichever cell left first
        }
      }
    }
  }
  for (int row = box.y; row < box.y + box.height; ++row) {
    for (int col = box.x; col < box.x + box.width; ++col) {
      const int index = indexOf(col, row);
      ASSERT_EQ(field.reachable(col, row), parent[index] >= 0) << col << ", " << row;
      if (parent[index] < 0) continue;
      EXPECT_EQ(field.cost(col, row), cost[index]) << col << ", " << row;
      EXPECT_EQ(field.label(col, row), label[index]) << col << ", " << row;
      const std::vector<cv::Point> path = field.pathFrom(col, row);
      const cv::Point next = path.size() > 1 ? path[1] : path[0];
      EXPECT_EQ(indexOf(next.x, next.y), parent[index]) << col << ", " << row;
    }
  }
  EXPECT_GT(ties, 0);
}

TEST(CostToGoFieldTest, AnswersTheSameWhateverOrderTheCellsAreAskedIn) {
  // The wavefront spreads only as far as the queries need. Three fields from the same goals, on
  // a floor with a closed room (unreachable cells) and equal-cost ties: one asked cell by cell
  // from a goal outwards (row order), one from the far corner back, one first at an unreachable
  // cell (which spreads the wavefront over everything). Every answer must agree.
  TestGrid cells(40, 30);
  cells.free(0, 0, 39, 29).occupied(19, 8, 20, 21).occupied(28, 2, 36, 2).occupied(28, 10, 36, 10);
  cells.occupied(28, 2, 28, 10).occupied(36, 2, 36, 10);  // the closed room, x 2.9-3.5, y 0.3-0.9
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  const std::vector<GoalCell> goals = {GoalCell{5, 5, 0.0, 0}, GoalCell{5, 24, 0.0, 1}, GoalCell{12, 15, 0.3, 2}};
  const cv::Rect box = grid.freeCells();
  CostToGoField forward(grid, plainOptions(0.15)), backward(grid, plainOptions(0.15)), closed_first(grid, plainOptions(0.15));
  for (CostToGoField* field : {&forward, &backward, &closed_first}) field->compute(goals);
  ASSERT_TRUE(closed_first.traversable(32, 6));
  EXPECT_FALSE(closed_first.reachable(32, 6));
  int reachable = 0;
  for (int i = 0; i < box.area(); ++i) {
    const int col = box.x + i % box.width, row = box.y + i / box.width;
    const int back_col = box.x + (box.area() - 1 - i) % box.width, back_row = box.y + (box.area() - 1 - i) / box.width;
    backward.cost(back_col, back_row);
    ASSERT_EQ(forward.reachable(col, row), closed_first.reachable(col, row)) << col << ", " << row;
    EXPECT_EQ(forward.cost(col, row), closed_first.cost(col, row)) << col << ", " << row;
    EXPECT_EQ(forward.label(col, row), closed_first.label(col, row)) << col << ", " << row;
    EXPECT_EQ(forward.pathFrom(col, row), closed_first.pathFrom(col, row)) << col << ", " << row;
    reachable += forward.reachable(col, row) ? 1 : 0;
  }
  for (int row = box.y; row < box.y + box.height; ++row) {
    for (int col = box.x; col < box.x + box.width; ++col) {
      EXPECT_EQ(backward.cost(col, row), forward.cost(col, row)) << col << ", " << row;
      EXPECT_EQ(backward.label(col, row), forward.label(col, row)) << col << ", " << row;
      EXPECT_EQ(backward.pathFrom(col, row), forward.pathFrom(col, row)) << col << ", " << row;
    }
  }
  EXPECT_GT(reachable, 500);
}

TEST(CostToGoFieldTest, MatchesRelaxationToAFixedPointOnAClutteredFloorWithRepulsion) {
  // A 6 m x 5 m floor with 40 random obstacle blocks, unknown patches and three goals with
  // different seed costs. The reference knows nothing of queues: it relaxes every step until no
  // cost falls (Bellman-Ford), with the step cost the class documents.
  TestGrid cells(60, 50);
  cells.free(0, 0, 59, 49);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> col_of(0, 57), row_of(0, 47), size_of(0, 2);
  for (int k = 0; k < 40; ++k) {
    const int col = col_of(random), row = row_of(random);
    if (k % 4 == 0) {
      cells.unknown(col, row, col + size_of(random), row + size_of(random));
    } else {
      cells.occupied(col, row, col + size_of(random), row + size_of(random));
    }
  }
  const NavigationGrid grid(cells.grid(), {}, NavigationGridOptions{});
  CostToGoOptions options;
  options.body_radius_m = 0.2;
  options.repulsion_distance_m = 0.4;
  options.repulsion_weight = 4.0;
  CostToGoField field(grid, options);
  std::vector<GoalCell> goals;
  for (const GoalCell goal : {GoalCell{3, 3, 0.0, 0}, GoalCell{55, 44, 0.7, 1}, GoalCell{30, 25, 1.5, 2}}) {
    if (field.traversable(goal.col, goal.row)) goals.push_back(goal);
  }
  ASSERT_GE(goals.size(), 2u);
  field.compute(goals);

  const double kInf = std::numeric_limits<double>::infinity();
  const auto weight = [&](int col, int row) {
    const double s = std::clamp(1.0 - (grid.obstacleDistance(col, row) - options.body_radius_m) / options.repulsion_distance_m,
                                0.0, 1.0);
    return 1.0 + options.repulsion_weight * s * s;
  };
  std::vector<double> cost(60 * 50, kInf);
  for (const GoalCell& goal : goals) cost[goal.row * 60 + goal.col] = std::min(cost[goal.row * 60 + goal.col], goal.seed_cost);
  for (bool changed = true; changed;) {
    changed = false;
    for (int row = 0; row < 50; ++row) {
      for (int col = 0; col < 60; ++col) {
        if (!field.traversable(col, row) || cost[row * 60 + col] == kInf) continue;
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int c = col + dc, r = row + dr;
            if ((dr == 0 && dc == 0) || c < 0 || r < 0 || c >= 60 || r >= 50 || !field.traversable(c, r)) continue;
            if (dr != 0 && dc != 0 && (!field.traversable(col + dc, row) || !field.traversable(col, row + dr))) continue;
            const double step = std::hypot(dr, dc) * 0.1 * 0.5 * (weight(col, row) + weight(c, r));
            if (cost[row * 60 + col] + step < cost[r * 60 + c] - 1e-12) {
              cost[r * 60 + c] = cost[row * 60 + col] + step;
              changed = true;
            }
          }
        }
      }
    }
  }
  int reachable = 0;
  for (int row = 0; row < 50; ++row) {
    for (int col = 0; col < 60; ++col) {
      const double expected = cost[row * 60 + col];
      ASSERT_EQ(field.reachable(col, row), expected != kInf) << col << ", " << row;
      if (expected == kInf) continue;
      ++reachable;
      EXPECT_NEAR(field.cost(col, row), expected, 1e-6) << col << ", " << row;
      // The path descends to a goal whose label the cell carries.
      const std::vector<cv::Point> path = field.pathFrom(col, row);
      const cv::Point end = path.back();
      const auto goal = std::find_if(goals.begin(), goals.end(),
                                     [&](const GoalCell& g) { return g.col == end.x && g.row == end.y; });
      ASSERT_NE(goal, goals.end());
      EXPECT_EQ(field.label(col, row), goal->label);
    }
  }
  EXPECT_GT(reachable, 1500);
}

}  // namespace
}  // namespace stereonav
