// The stereo engine against the renderer's exact disparity on textured office views: the
// accuracy the rest of the pipeline (and the map scores of office_run_test.cc) rests on.

#include <gtest/gtest.h>

#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <iostream>

#include "common/ini_section.h"
#include "disparity/disparity_engine.h"
#include "disparity/disparity_image.h"
#include "rig/camera_rig.h"
#include "simulator/moving_traffic.h"
#include "simulator/rig_renderer.h"
#include "simulator/world_loader.h"

namespace stereonav {
namespace {

const std::string kSourceDir = STEREONAV_SOURCE_DIR;

struct Agreement {
  size_t valid = 0;
  size_t within_one_pixel = 0;
  size_t pixels = 0;
};

// Matches the frames rendered at `poses` with the shipped office_run.ini's [rig] and [stereo].
Agreement matchOfficeViews(const std::vector<mrpt::poses::CPose2D>& poses) {
  const mrpt::config::CConfigFile config(kSourceDir + "/ini/office_run.ini");
  IniSection rig_section(config, "rig");
  const CameraRig rig = loadCameraRig(rig_section);
  IniSection stereo_section(config, "stereo");
  StereoMatcher matcher(loadStereoOptions(stereo_section));

  const World world = loadWorld(kSourceDir + "/ini/worlds/office.ini");
  RigRenderer renderer(world, rig, SensorOptions{});  // the simulator's default sensor noise
  Agreement agreement;
  cv::Mat1f disparity;
  for (const mrpt::poses::CPose2D& pose : poses) {
    const RigImages images = renderer.render(pose, 0.0, MovingTraffic(world).solids());
    StereoFrame frame{images.reference, {}};
    for (size_t i = 0; i < rig.secondaries.size(); ++i) frame.secondaries.push_back({images.secondaries[i], rig.secondaries[i]});
    matcher.compute(frame, disparity);
    for (int y = 0; y < disparity.rows; ++y) {
      for (int x = 0; x < disparity.cols; ++x) {
        ++agreement.pixels;
        const float truth = images.true_disparity(y, x);
        if (!isValidDisparity(disparity(y, x)) || !isValidDisparity(truth)) continue;
        ++agreement.valid;
        agreement.within_one_pixel += std::abs(disparity(y, x) - truth) <= 1.0f;
      }
    }
  }
  return agreement;
}

TEST(StereoAccuracy, ValidPixelsOfTexturedOfficeViewsAgreeWithTheTruthWithinOnePixel) {
  // Down the corridor from the start, into the meeting room N1, at the lab S2's balustrade.
  const Agreement agreement = matchOfficeViews({mrpt::poses::CPose2D(1.0, 7.5, 0.0),
                                                mrpt::poses::CPose2D(2.5, 8.5, M_PI / 2),
                                                mrpt::poses::CPose2D(8.5, 5.5, -M_PI / 2)});
  const double valid_share = static_cast<double>(agreement.valid) / agreement.pixels;
  const double agreeing = static_cast<double>(agreement.within_one_pixel) / agreement.valid;
  std::cout << "valid " << valid_share << " of all pixels; " << agreeing << " of them within 1 px of the truth\n";
  // Enough pixels survive validation for the agreement to mean something.
  EXPECT_GT(valid_share, 0.3);
  EXPECT_GE(agreeing, 0.95) << agreement.within_one_pixel << " of " << agreement.valid << " valid pixels";
}

}  // namespace
}  // namespace stereonav
