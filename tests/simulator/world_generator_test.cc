#include "simulator/world_generator.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <opencv2/imgproc.hpp>

#include <set>

#include "simulator/ground_truth_map.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

// The world's ground-truth map, as `stereonav generate` writes it, from the world file alone.
GroundTruthMap truthOf(const GeneratedWorld& world) {
  mrpt::config::CConfigFileMemory config(world.ini_text);
  return GroundTruthMap(loadWorld(config, "seed " + std::to_string(world.seed)), GroundTruthMapOptions{});
}

cv::Point cellOf(const GroundTruthMap& truth, double x, double y) {
  return {static_cast<int>(std::floor((x - truth.xMin()) / truth.resolution())),
          static_cast<int>(std::floor((y - truth.yMin()) / truth.resolution()))};
}

bool freeAt(const GroundTruthMap& truth, double x, double y) {
  const cv::Point c = cellOf(truth, x, y);
  return truth.cell(c.x, c.y) == GroundTruthMap::kFree;
}

// Cells a round robot of `radius` can stand on (every occupied cell farther than radius from its
// centre) that it reaches from `start`, by breadth-first search over the 8 neighbours.
cv::Mat1b reachable(const GroundTruthMap& truth, double radius, cv::Point start) {
  cv::Mat1b free(truth.height(), truth.width());
  for (int iy = 0; iy < truth.height(); ++iy) {
    for (int ix = 0; ix < truth.width(); ++ix) free(iy, ix) = truth.cell(ix, iy) == GroundTruthMap::kFree ? 255 : 0;
  }
  cv::Mat1f clearance;
  cv::distanceTransform(free, clearance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::Mat1b reached = cv::Mat1b::zeros(free.size());
  const auto standable = [&](cv::Point p) {
    return p.x >= 0 && p.y >= 0 && p.x < free.cols && p.y < free.rows &&
           clearance(p) * truth.resolution() > radius;
  };
  if (!standable(start)) return reached;
  std::vector<cv::Point> queue{start};
  reached(start) = 1;
  for (size_t i = 0; i < queue.size(); ++i) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const cv::Point next = queue[i] + cv::Point(dx, dy);
        if (standable(next) && !reached(next)) {
          reached(next) = 1;
          queue.push_back(next);
        }
      }
    }
  }
  return reached;
}

TEST(WorldGeneratorTest, TheSameSeedGivesTheSameWorld) {
  EXPECT_EQ(generateWorld(7).ini_text, generateWorld(7).ini_text);
  EXPECT_NE(generateWorld(7).ini_text, generateWorld(8).ini_text);
}

TEST(WorldGeneratorTest, DoorsAreOpenAndAsWideAsStatedOnTheTruthMap) {
  const GeneratedWorld world = generateWorld(3);
  const GroundTruthMap truth = truthOf(world);
  ASSERT_FALSE(world.doors.empty());
  for (const GeneratedDoor& door : world.doors) {
    // Along the wall through the door's centre: free across the stated width (less a cell at
    // each side for the raster), wall just beyond it.
    const double half = door.clear_width_m / 2 - truth.resolution();
    const double jamb = door.clear_width_m / 2 + 0.05;
    for (double s = -half; s <= half; s += truth.resolution() / 2) {
      EXPECT_TRUE(freeAt(truth, door.x + (door.along_x ? s : 0), door.y + (door.along_x ? 0 : s)))
          << "door at " << door.x << " " << door.y << ", offset " << s;
    }
    for (double side : {-1.0, 1.0}) {
      EXPECT_FALSE(freeAt(truth, door.x + (door.along_x ? side * jamb : 0), door.y + (door.along_x ? 0 : side * jamb)))
          << "no jamb beside the door at " << door.x << " " << door.y;
    }
  }
}

// Seeds 1-20, the benchmark's worlds: the stated ranges, every room reachable from the start for
// the robot, the flat share.
TEST(WorldGeneratorTest, TwentySeedsKeepTheirPromises) {
  std::set<std::string> kinds;
  size_t with_person = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const GeneratedWorld world = generateWorld(seed);
    kinds.insert(world.kind);
    with_person += world.moving_person;
    EXPECT_GE(world.footprint.width(), 8.0);
    EXPECT_LE(world.footprint.width(), 30.0);
    EXPECT_GE(world.footprint.depth(), 8.0);
    EXPECT_LE(world.footprint.depth(), 20.0);
    EXPECT_GE(world.rooms.size(), 3u);
    EXPECT_LE(world.rooms.size(), 12u);
    // One door joins each room to the rest: n rooms, n - 1 doors.
    EXPECT_EQ(world.doors.size(), world.rooms.size() - 1);
    for (const GeneratedDoor& door : world.doors) {
      EXPECT_GE(door.clear_width_m, kGeneratedDoorMinWidthM);
      EXPECT_LE(door.clear_width_m, kGeneratedDoorMaxWidthM);
    }
    const double flat = static_cast<double>(world.flat_wall_sections) / static_cast<double>(world.wall_sections);
    EXPECT_GE(flat, 0.2);
    EXPECT_LE(flat, 0.4);
    EXPECT_GT(world.furniture, 0u);

    const GroundTruthMap truth = truthOf(world);
    const cv::Mat1b reached = reachable(truth, kGeneratedRobotRadiusM, cellOf(truth, world.start_x, world.start_y));
    for (const FloorRect& room : world.rooms) {
      const cv::Point a = cellOf(truth, room.x0, room.y0), b = cellOf(truth, room.x1, room.y1);
      EXPECT_GT(cv::countNonZero(reached(cv::Range(a.y, b.y), cv::Range(a.x, b.x))), 0)
          << "room " << room.x0 << " " << room.y0 << " - " << room.x1 << " " << room.y1 << " is out of reach";
    }
    // The outer walls are in the truth map, the start is free.
    EXPECT_FALSE(freeAt(truth, world.footprint.x0, 0.5 * (world.footprint.y0 + world.footprint.y1)));
    EXPECT_TRUE(freeAt(truth, world.start_x, world.start_y));
  }
  EXPECT_EQ(kinds.size(), 3u);
  EXPECT_GT(with_person, 0u);
  EXPECT_LT(with_person, 20u);
}

}  // namespace
}  // namespace stereonav
