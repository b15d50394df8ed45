#include "simulator/motion_plan.h"

#include <gtest/gtest.h>

#include "common/ini_section.h"

namespace stereonav {
namespace {

std::string parseError(const std::string& text) {
  try {
    parseMotionPlan(text, "plan.txt");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(MotionPlan, WaypointsOrTimedCommands) {
  const MotionPlan waypoints = parseMotionPlan("# a square\n1 0\n\n1 1\n  0 1\n", "plan.txt");
  ASSERT_EQ(waypoints.waypoints.size(), 3u);
  EXPECT_DOUBLE_EQ(waypoints.waypoints[2].y, 1.0);
  EXPECT_TRUE(waypoints.commands.empty());
  const MotionPlan commands = parseMotionPlan("0 1 0\n2.5 0.5 -0.2\n4 0 0\n", "plan.txt");
  ASSERT_EQ(commands.commands.size(), 3u);
  EXPECT_DOUBLE_EQ(commands.commands[1].time_s, 2.5);
  EXPECT_DOUBLE_EQ(commands.commands[1].turn_rate, -0.2);
}

TEST(MotionPlan, ErrorsNameFileAndLine) {
  EXPECT_NE(parseError("1 0\n0 1 0\n").find("plan.txt:2"), std::string::npos);
  EXPECT_NE(parseError("0 1 0\n1 0\n").find("plan.txt:2"), std::string::npos);
  EXPECT_NE(parseError("1 0\n2 x\n").find("plan.txt:2"), std::string::npos);
  EXPECT_NE(parseError("1\n").find("plan.txt:1"), std::string::npos);
  EXPECT_NE(parseError("0 1 0\n3 0 0\n2 0 0\n").find("plan.txt:3: times must increase"), std::string::npos);
  EXPECT_NE(parseError("1 1 0\n3 0 0\n").find("plan.txt:1"), std::string::npos);
  EXPECT_NE(parseError("# nothing\n").find("plan.txt"), std::string::npos);
  EXPECT_NE(parseError("0 1 0\n").find("plan.txt"), std::string::npos);
}

TEST(MotionPlan, MissingFileIsNamed) {
  try {
    loadMotionPlan("/nonexistent/plan.txt");
    FAIL();
  } catch (const ConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/plan.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace stereonav
