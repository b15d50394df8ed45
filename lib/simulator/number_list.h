#pragma once

#include <string>
#include <vector>

namespace stereonav {

// Parses whitespace-separated numbers, e.g. "0.4 0.1 0.025". Throws ConfigError "<what>: ..."
// when a token is not a number or, if `expected_count` >= 0, when the count differs.
std::vector<double> parseNumberList(const std::string& text, const std::string& what,
                                    int expected_count = -1);

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// Parses a point list "x y; x y; ...", as used for wall polylines and obstacle paths. Throws
// ConfigError "<what>: ..." on malformed text or fewer than `minimum_count` points.
std::vector<Point2> parsePointList(const std::string& text, const std::string& what,
                                   size_t minimum_count);

}  // namespace stereonav
