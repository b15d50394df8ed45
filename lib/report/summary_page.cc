#include "report/summary_page.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace stereonav {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

constexpr double kPlotWidth = 600.0, kPlotHeight = 240.0, kMargin = 40.0;

std::string coverageSvg(const std::vector<CoverageSample>& samples) {
  std::ostringstream svg;
  const double end_s = samples.empty() ? 0.0 : samples.back().time_s;
  svg << std::fixed << std::setprecision(1) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
      << kPlotWidth + 2 * kMargin << "\" height=\"" << kPlotHeight + 2 * kMargin << "\">\n"
      << "<g transform=\"translate(" << kMargin << "," << kMargin << ")\" font-size=\"12\">\n"
      << "<rect width=\"" << kPlotWidth << "\" height=\"" << kPlotHeight << "\" fill=\"none\" stroke=\"#888\"/>\n";
  for (int percent = 25; percent < 100; percent += 25) {
    const double y = kPlotHeight * (1.0 - percent / 100.0);
    svg << "<line x1=\"0\" x2=\"" << kPlotWidth << "\" y1=\"" << y << "\" y2=\"" << y << "\" stroke=\"#ddd\"/>"
        << "<text x=\"-6\" y=\"" << y + 4 << "\" text-anchor=\"end\">" << percent << "%</text>\n";
  }
  svg << "<text x=\"-6\" y=\"4\" text-anchor=\"end\">100%</text><text x=\"-6\" y=\"" << kPlotHeight + 4
      << "\" text-anchor=\"end\">0%</text>\n"
      << "<text x=\"0\" y=\"" << kPlotHeight + 18 << "\">0 s</text><text x=\"" << kPlotWidth << "\" y=\""
      << kPlotHeight + 18 << "\" text-anchor=\"end\">" << end_s << " s simulated</text>\n"
      << "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"2\" points=\""
      << svgPolylinePoints(samples, &CoverageSample::seen_coverage, kPlotWidth, kPlotHeight) << "\"/>\n"
      << "<polyline fill=\"none\" stroke=\"#c00\" stroke-width=\"2\" points=\""
      << svgPolylinePoints(samples, &CoverageSample::coverage, kPlotWidth, kPlotHeight) << "\"/>\n"
      << "<text x=\"8\" y=\"16\" fill=\"#c00\">coverage: reachable floor mapped free</text>"
      << "<text x=\"8\" y=\"32\" fill=\"#999\">seen: reachable floor mapped at all</text>\n"
      << "</g></svg>\n";
  return svg.str();
}

}  // namespace

std::string svgPolylinePoints(const std::vector<CoverageSample>& samples, double CoverageSample::*value,
                              double width, double height) {
  std::ostringstream points;
  points << std::fixed << std::setprecision(1);
  const double end_s = samples.empty() ? 0.0 : samples.back().time_s;
  for (const CoverageSample& sample : samples) {
    const double x = end_s > 0.0 ? width * sample.time_s / end_s : 0.0;
    const double y = height * (1.0 - std::clamp(sample.*value, 0.0, 1.0));
    points << (&sample == &samples.front() ? "" : " ") << x << "," << y;
  }
  return points.str();
}

std::string summaryHtml(const SummaryPage& page) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << escaped(page.title)
       << "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:70em}td{padding:0.2em 1em}"
          "img{max-width:100%;image-rendering:pixelated}figure{display:inline-block;vertical-align:top;margin:0 1em 1em 0}"
          "</style></head><body>\n<h1>"
       << escaped(page.title) << "</h1>\n<table>\n";
  for (const auto& [name, value] : page.facts) {
    html << "<tr><td>" << escaped(name) << "</td><td><b>" << escaped(value) << "</b></td></tr>\n";
  }
  html << "</table>\n";
  for (const auto& [caption, path] : page.images) {
    html << "<figure><img src=\"" << escaped(path) << "\" alt=\"" << escaped(caption) << "\"><figcaption>"
         << escaped(caption) << "</figcaption></figure>\n";
  }
  if (!page.coverage.empty()) html << "<h2>Coverage over time</h2>\n" << coverageSvg(page.coverage);
  if (!page.panels.empty()) {
    html << "<h2>Debug panels</h2>\n<p>Reference image, disparity (blue far, red near, white invalid, magenta "
            "removed as spikes), the column reading, depth per column, and the frame's OCC (black) and CLEAR "
            "(white) regions from above (paper figures 5 and 6).</p>\n";
    for (const auto& [caption, path] : page.panels) {
      html << "<figure><img src=\"" << escaped(path) << "\" alt=\"debug panel\"><figcaption>" << escaped(caption)
           << "</figcaption></figure>\n";
    }
  }
  html << "</body></html>\n";
  return html.str();
}

}  // namespace stereonav
