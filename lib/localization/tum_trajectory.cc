#include "localization/tum_trajectory.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.h"

namespace stereonav {

std::string toTumText(const std::vector<StampedPose>& trajectory) {
  std::ostringstream text;
  text << "# timestamp tx ty tz qx qy qz qw\n" << std::fixed;
  for (const StampedPose& stamped : trajectory) {
    const double half = stamped.pose.phi() / 2;
    text << std::setprecision(6) << stamped.time_s << ' ' << stamped.pose.x() << ' '
         << stamped.pose.y() << " 0 0 0 " << std::setprecision(9) << std::sin(half) << ' '
         << std::cos(half) << '\n';
  }
  return text.str();
}

void saveTumTrajectory(const std::string& path, const std::vector<StampedPose>& trajectory) {
  writeStringAtomically(path, toTumText(trajectory));
}

std::vector<StampedPose> loadTrajectory(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot read trajectory");
  std::vector<StampedPose> trajectory;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    const size_t comment = line.find('#');
    if (comment != std::string::npos) line.erase(comment);
    std::istringstream fields(line);
    std::vector<double> values;
    for (double value; fields >> value;) values.push_back(value);
    if (!fields.eof()) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": not a number");
    }
    if (values.empty()) continue;
    if (values.size() == 4) {
      trajectory.push_back({values[0], {values[1], values[2], values[3]}});
    } else if (values.size() == 8) {
      const double qz = values[6], qw = values[7];
      trajectory.push_back({values[0], {values[1], values[2], 2.0 * std::atan2(qz, qw)}});
      trajectory.back().pose.normalizePhi();
    } else {
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": expected 't x y phi' or TUM 't x y z qx qy qz qw'");
    }
  }
  return trajectory;
}

}  // namespace stereonav
