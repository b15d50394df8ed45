#include "simulator/motion_plan.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/ini_section.h"

namespace stereonav {
namespace {

constexpr double kMaxPlanValue = 1e6;

}  // namespace

MotionPlan parseMotionPlan(const std::string& text, const std::string& file_name) {
  MotionPlan plan;
  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = file_name + ":" + std::to_string(line_number);
    const std::vector<double> numbers = parseNumberList(line, where);
    // Coordinates, times and speeds far beyond any robot's are mistakes (and would make the
    // controller's arithmetic meaningless).
    for (double number : numbers) {
      if (std::abs(number) > kMaxPlanValue) {
        throw ConfigError(where + ": values must be in " + describeRange(-kMaxPlanValue, kMaxPlanValue) +
                          ", got '" + line + "'");
      }
    }
    if (numbers.size() == 2) {
      if (!plan.commands.empty()) throw ConfigError(where + ": waypoint 'x y' among timed commands 't v w'");
      plan.waypoints.push_back({numbers[0], numbers[1]});
    } else if (numbers.size() == 3) {
      if (!plan.waypoints.empty()) throw ConfigError(where + ": timed command 't v w' among waypoints 'x y'");
      if (plan.commands.empty() && numbers[0] != 0.0) {
        throw ConfigError(where + ": the first timed command must start at t = 0");
      }
      if (!plan.commands.empty() && numbers[0] <= plan.commands.back().time_s) {
        throw ConfigError(where + ": times must increase");
      }
      plan.commands.push_back({numbers[0], numbers[1], numbers[2]});
    } else {
      throw ConfigError(where + ": expected 'x y' (a waypoint) or 't v w' (a timed command), got '" +
                        line + "'");
    }
  }
  if (plan.waypoints.empty() && plan.commands.size() < 2) {
    throw ConfigError(file_name + ": no waypoints, or fewer than two timed commands (the last one ends the run)");
  }
  return plan;
}

MotionPlan loadMotionPlan(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw ConfigError(path + ": cannot open the path file");
  std::stringstream text;
  text << file.rdbuf();
  return parseMotionPlan(text.str(), path);
}

}  // namespace stereonav
