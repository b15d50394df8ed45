#include "evaluation/map_score.h"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "common/json_writer.h"
#include "evaluation/map_comparison.h"

namespace stereonav {
namespace {

double ratio(size_t part, size_t whole) { return whole == 0 ? 0.0 : static_cast<double>(part) / whole; }

}  // namespace

double MapScore::precision() const { return ratio(map_occupied_correct, map_occupied); }
double MapScore::recall() const { return ratio(truth_obstacles_found, truth_obstacles); }
double MapScore::falseFree() const { return ratio(truth_obstacles_free, truth_obstacles); }
double MapScore::coverage() const { return ratio(reachable_free_mapped_free, reachable_free); }

std::string MapScore::toText() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(4);
  const std::string obstacles = obstacles_in_view_only ? "true obstacle cells in view of the poses"
                                                       : "true obstacle cells";
  out << "occupied precision " << precision() << "  (" << map_occupied_correct << " of " << map_occupied
      << " map-occupied cells within " << tolerance_cells << " cell(s) of a true obstacle)\n"
      << "occupied recall    " << recall() << "  (" << truth_obstacles_found << " of " << truth_obstacles << " "
      << obstacles << " within " << tolerance_cells << " cell(s) of a map-occupied cell)\n"
      << "false free         " << falseFree() << "  (" << truth_obstacles_free << " of " << truth_obstacles << " "
      << obstacles << " mapped free)\n"
      << "coverage           " << coverage() << "  (" << reachable_free_mapped_free << " of " << reachable_free
      << (coverage_from_start ? " free cells reachable from the start" : " true free cells") << " mapped free)\n";
  return out.str();
}

std::string MapScore::toJson() const {
  JsonWriter json;
  json.beginObject()
      .key("precision").value(precision())
      .key("recall").value(recall())
      .key("false_free").value(falseFree())
      .key("coverage").value(coverage())
      .key("tolerance_cells").value(tolerance_cells)
      .key("obstacles_in_view_only").value(obstacles_in_view_only)
      .key("coverage_from_start").value(coverage_from_start)
      .key("map_occupied").value(map_occupied)
      .key("map_occupied_correct").value(map_occupied_correct)
      .key("truth_obstacles").value(truth_obstacles)
      .key("truth_obstacles_found").value(truth_obstacles_found)
      .key("truth_obstacles_free").value(truth_obstacles_free)
      .key("reachable_free").value(reachable_free)
      .key("reachable_free_mapped_free").value(reachable_free_mapped_free)
      .endObject();
  return json.str();
}

MapScore scoreMap(const RosMap& map, const RosMap& truth, const MapScoreOptions& options) {
  const MapComparison cells = compareOnTruthCells(map, truth, options);
  MapScore score;
  score.tolerance_cells = options.tolerance_cells;
  score.obstacles_in_view_only = !options.poses.empty();
  score.coverage_from_start = cells.coverage_from_start;
  score.map_occupied = cv::countNonZero(cells.map_occupied);
  score.map_occupied_correct = cv::countNonZero(cells.map_occupied & cells.near_truth_obstacle);
  score.truth_obstacles = cv::countNonZero(cells.scored_obstacles);
  score.truth_obstacles_found = cv::countNonZero(cells.scored_obstacles & cells.near_map_obstacle);
  score.truth_obstacles_free = cv::countNonZero(cells.scored_obstacles & cells.map_free);
  score.reachable_free = cv::countNonZero(cells.free_space);
  score.reachable_free_mapped_free = cv::countNonZero(cells.free_space & cells.map_free);
  return score;
}

}  // namespace stereonav
