#include "report/summary_page.h"

#include <gtest/gtest.h>

namespace stereonav {
namespace {

TEST(SvgPolylinePoints, MapsTimeToWidthAndFractionToHeightFromTheBottom) {
  const std::vector<CoverageSample> samples{{0.0, 0.0, 0.2}, {5.0, 0.5, 0.6}, {10.0, 1.0, 1.0}};
  EXPECT_EQ(svgPolylinePoints(samples, &CoverageSample::coverage, 100.0, 50.0), "0.0,50.0 50.0,25.0 100.0,0.0");
  EXPECT_EQ(svgPolylinePoints(samples, &CoverageSample::seen_coverage, 100.0, 50.0), "0.0,40.0 50.0,20.0 100.0,0.0");
  EXPECT_EQ(svgPolylinePoints({}, &CoverageSample::coverage, 100.0, 50.0), "");
}

TEST(SummaryHtml, ShowsFactsImagesCurveAndPanelsEscaped) {
  SummaryPage page;
  page.title = "room <1> & co";
  page.facts = {{"coverage", "91.2%"}};
  page.images = {{"map \"with\" path", "path.png"}};
  page.coverage = {{0.0, 0.1, 0.2}, {2.0, 0.9, 0.95}};
  page.panels = {{"frame 0, t = 0 s", "panels/panel_000000.png"}};
  const std::string html = summaryHtml(page);
  EXPECT_NE(html.find("<title>room &lt;1&gt; &amp; co</title>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>coverage</td><td><b>91.2%</b></td>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"path.png\" alt=\"map &quot;with&quot; path\">"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"panels/panel_000000.png\" alt=\"debug panel\"><figcaption>frame 0, t = 0 s<"),
            std::string::npos);
  // Both curves, in the 600 x 240 plot: coverage 0.1 at t = 0 is 216 px down, 0.9 at the end 24.
  EXPECT_NE(html.find("points=\"0.0,216.0 600.0,24.0\""), std::string::npos) << html;
  EXPECT_NE(html.find("points=\"0.0,192.0 600.0,12.0\""), std::string::npos);
  EXPECT_NE(html.find("2.0 s simulated"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
