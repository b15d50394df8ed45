#include "simulator/number_list.h"

#include <sstream>

#include "common/ini_section.h"

namespace stereonav {

std::vector<double> parseNumberList(const std::string& text, const std::string& what,
                                    int expected_count) {
  std::vector<double> numbers;
  std::stringstream stream(text);
  std::string token;
  while (stream >> token) {
    double number = 0.0;
    if (!parseFiniteDouble(token, number)) {
      throw ConfigError(what + ": '" + token + "' is not a finite number (in '" + text + "')");
    }
    numbers.push_back(number);
  }
  if (expected_count >= 0 && numbers.size() != static_cast<size_t>(expected_count)) {
    throw ConfigError(what + ": expected " + std::to_string(expected_count) + " numbers, got '" +
                      text + "'");
  }
  return numbers;
}

std::vector<Point2> parsePointList(const std::string& text, const std::string& what,
                                   size_t minimum_count) {
  std::vector<Point2> points;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ';')) {
    if (item.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<double> xy = parseNumberList(item, what + " (points are 'x y; x y; ...')", 2);
    points.push_back({xy[0], xy[1]});
  }
  if (points.size() < minimum_count) {
    throw ConfigError(what + ": expected at least " + std::to_string(minimum_count) +
                      " points 'x y; x y; ...', got '" + text + "'");
  }
  return points;
}

}  // namespace stereonav
