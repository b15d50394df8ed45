#pragma once

#include <string>
#include <utility>
#include <vector>

#include "report/coverage_timeline.h"

namespace stereonav {

// What one page shows about a run: a person looks at it rather than reads it.
struct SummaryPage {
  std::string title;
  std::vector<std::pair<std::string, std::string>> facts;  // name, value, shown as a table
  std::vector<std::pair<std::string, std::string>> images;  // caption, path relative to the page
  std::vector<CoverageSample> coverage;                    // drawn as a curve
  std::vector<std::pair<std::string, std::string>> panels;  // debug panels: caption, path
};

// The points attribute of an SVG polyline drawing `value` of each sample in a width x height box:
// time from 0 (left) to the last sample's (right), 0 (bottom) to 1 (top).
std::string svgPolylinePoints(const std::vector<CoverageSample>& samples, double CoverageSample::*value,
                              double width, double height);

// A self-contained HTML page (images by relative path, the curve as inline SVG).
std::string summaryHtml(const SummaryPage& page);

}  // namespace stereonav
