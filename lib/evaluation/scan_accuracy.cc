#include "evaluation/scan_accuracy.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace stereonav {
namespace {

// Distance on the floor from the robot's centre to what column x reads at row y and disparity d.
double floorRange(const CameraRig& rig, int x, int y, double disparity) {
  const mrpt::math::TPoint2D reading = rig.readingOnRobot(x, y, disparity);
  return std::hypot(reading.x, reading.y);
}

double share(size_t part, size_t whole) { return whole == 0 ? 0.0 : static_cast<double>(part) / whole; }

}  // namespace

ScanAccuracy& ScanAccuracy::operator+=(const ScanAccuracy& other) {
  frames += other.frames;
  columns += other.columns;
  read += other.read;
  agreeing += other.agreeing;
  agreeing_error_sum += other.agreeing_error_sum;
  agreeing_square_error += other.agreeing_square_error;
  phantoms += other.phantoms;
  close_phantoms += other.close_phantoms;
  too_near += other.too_near;
  close_obstacles += other.close_obstacles;
  close_misses += other.close_misses;
  return *this;
}

double ScanAccuracy::agreeingMeanError() const {
  return agreeing == 0 ? 0.0 : agreeing_error_sum / static_cast<double>(agreeing);
}

double ScanAccuracy::agreeingRmsError() const {
  return agreeing == 0 ? 0.0 : std::sqrt(agreeing_square_error / static_cast<double>(agreeing));
}

std::string ScanAccuracy::toText() const {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << frames << " frames, " << 100.0 * share(read, columns)
       << "% of columns read; of them " << 100.0 * share(agreeing, read) << "% agree with the truth (mean "
       << std::showpos << std::setprecision(3) << agreeingMeanError() << std::noshowpos << ", rms " << agreeingRmsError() << std::setprecision(2) << " px), "
       << 100.0 * share(phantoms, read) << "% read nearer than anything there (" << 100.0 * share(close_phantoms, read)
       << "% within reach); " << 100.0 * share(close_misses, close_obstacles)
       << "% of the columns with an obstacle within reach read it farther or not at all, and "
       << 100.0 * share(too_near, columns) << "% see one nearer than the matcher searches";
  return text.str();
}

std::string ScanAccuracy::toJson() const {
  std::ostringstream json;
  json << "{\"frames\": " << frames << ", \"columns\": " << columns << ", \"read\": " << read
       << ", \"agreeing\": " << agreeing << ", \"agreeing_mean_px\": " << agreeingMeanError()
       << ", \"agreeing_rms_px\": " << agreeingRmsError()
       << ", \"phantoms\": " << phantoms << ", \"close_phantoms\": " << close_phantoms
       << ", \"too_near\": " << too_near << ", \"close_obstacles\": " << close_obstacles
       << ", \"close_misses\": " << close_misses << "}";
  return json.str();
}

ScanAccuracy compareScans(const DisparityScan& measured, const DisparityScan& truth, const CameraRig& rig,
                          const ScanAccuracyOptions& options) {
  if (measured.columns() != truth.columns()) {
    throw std::invalid_argument("scans of " + std::to_string(measured.columns()) + " and " +
                                std::to_string(truth.columns()) + " columns");
  }
  ScanAccuracy accuracy;
  accuracy.frames = 1;
  accuracy.columns = static_cast<size_t>(measured.columns());
  for (int x = 0; x < measured.columns(); ++x) {
    // Where the truth sees nothing in the body volume, any reading is nearer than what is there.
    const double true_disparity = truth.valid(x) ? truth.column_disparity[x] : 0.0;
    const bool too_near = truth.valid(x) && true_disparity > options.max_disparity;
    const bool close_obstacle = truth.valid(x) && !too_near &&
                                floorRange(rig, x, truth.column_row[x], true_disparity) <= options.close_range_m;
    accuracy.too_near += too_near ? 1 : 0;
    accuracy.close_obstacles += close_obstacle ? 1 : 0;
    if (!measured.valid(x)) {
      accuracy.close_misses += close_obstacle ? 1 : 0;
      continue;
    }
    const double disparity = measured.column_disparity[x];
    ++accuracy.read;
    const double error = disparity - true_disparity;
    if (truth.valid(x) && std::abs(error) <= options.agree_px) {
      ++accuracy.agreeing;
      accuracy.agreeing_error_sum += error;
      accuracy.agreeing_square_error += error * error;
    }
    if (disparity > true_disparity + options.wrong_px) {
      ++accuracy.phantoms;
      accuracy.close_phantoms += floorRange(rig, x, measured.column_row[x], disparity) <= options.close_range_m ? 1 : 0;
    }
    accuracy.close_misses += close_obstacle && disparity < true_disparity - options.wrong_px ? 1 : 0;
  }
  return accuracy;
}

}  // namespace stereonav
