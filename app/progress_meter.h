#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>

namespace stereonav {

// A one-line progress bar for a terminal, redrawn in place at most ten times a second:
//   mapping [##########..........]  30/60  50%  24.8 frames/s  ETA 0:01
// Without a known total it shows the count and the rate only. `label` names the work ("mapping").
class ProgressMeter {
 public:
  ProgressMeter(std::ostream& out, std::string label, std::optional<size_t> total);

  void update(size_t done);
  // Draws the final state and ends the line.
  void finish(size_t done);

 private:
  void draw(size_t done);

  std::ostream& out_;
  std::string label_;
  std::optional<size_t> total_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace stereonav
