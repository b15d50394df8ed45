// The `stereonav disparity` command end to end: the built binary on the bundled tsukuba views.
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "disparity/disparity_evaluation.h"
#include "disparity/disparity_image.h"
#include "disparity/disparity_io.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

const std::string kData = std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/";

struct CommandResult {
  int exit_code;
  std::string output;  // stdout and stderr
};

class DisparityCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(path("stereo.ini")) << "# tsukuba: disparities 5..14\n[stereo]\nmax_disparity = 15\n"
                                         "uniqueness_threshold = 0.04\n";
  }

  std::string path(const std::string& name) const { return scratch_.file(name); }

  CommandResult run(const std::string& arguments) const {
    const std::string log = path("log.txt");
    const std::string command =
        std::string(STEREONAV_BINARY_DIR) + "/bin/stereonav disparity " + arguments + " > " + log + " 2>&1";
    const int status = std::system(command.c_str());
    std::stringstream output;
    output << std::ifstream(log).rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output.str()};
  }

  // Reference and right camera with the test's config, plus `extra`.
  CommandResult runBinocular(const std::string& extra) const {
    return run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
               "scene1.row3.col4.ppm:1:0 " + extra);
  }

  // Exits with `code` and prints one line containing `expected`, and writes no output file.
  void expectError(const CommandResult& result, int code, const std::string& expected) const {
    EXPECT_EQ(result.exit_code, code) << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_FALSE(std::filesystem::exists(path("out.pfm")));
  }

  test_support::ScratchDirectory scratch_;
};

TEST_F(DisparityCommandTest, MultiBaselineWritesPfmColourAndScores) {
  const CommandResult result = run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
                         "scene1.row3.col4.ppm:1:0 --cam " + kData + "scene1.row3.col1.ppm:-2:0 --cam " + kData +
                         "scene1.row3.col2.ppm:-1:0 --cam " + kData + "scene1.row3.col5.ppm:2:0 --out " +
                         path("out.pfm") + " --colour " + path("colour.png") + " --gt " + kData +
                         "truedisp.row3.col3.pgm --gt-scale 16");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("bad-1.0"), std::string::npos) << result.output;
  const cv::Mat1f disparity = readDisparityPfm(path("out.pfm"));
  const DisparityEvaluation scores =
      evaluateDisparity(disparity, loadMiddleburyGroundTruth(kData + "truedisp.row3.col3.pgm", 16.0));
  EXPECT_GE(scores.density, 0.85);
  EXPECT_LE(scores.bad_1, 0.03);
  EXPECT_EQ(cv::imread(path("colour.png")).size(), disparity.size());
}

TEST_F(DisparityCommandTest, CommandLineOverridesTheIni) {
  // The ini searches up to 15, which reaches the lamp (disparity 14); --max-disp 9 cannot, and
  // --subpixel gives fractional disparities where the ini's whole-pixel search cannot.
  ASSERT_EQ(runBinocular("--out " + path("d15.pfm")).exit_code, 0);
  ASSERT_EQ(runBinocular("--out " + path("d9.pfm") + " --max-disp 9 --window 9 --subpixel").exit_code, 0);
  const cv::Mat1f d15 = readDisparityPfm(path("d15.pfm")), d9 = readDisparityPfm(path("d9.pfm"));
  const auto count = [](const cv::Mat1f& disparity, const std::function<bool(float)>& test) {
    return std::count_if(disparity.begin(), disparity.end(), [&](float d) { return isValidDisparity(d) && test(d); });
  };
  EXPECT_GT(count(d15, [](float d) { return d >= 12.0f; }), 1000);
  EXPECT_EQ(count(d9, [](float d) { return d > 9.0f; }), 0);
  EXPECT_EQ(count(d15, [](float d) { return d != std::round(d); }), 0);
  EXPECT_GT(count(d9, [](float d) { return d != std::round(d); }), 1000);
}

TEST_F(DisparityCommandTest, OpenCvBackendChosenOnTheCommandLine) {
  const CommandResult result = runBinocular("--out " + path("bm.pfm") + " --backend bm");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("backend bm"), std::string::npos) << result.output;
}

TEST_F(DisparityCommandTest, SpikeRemovalAppliesTheIniSection) {
  const auto countValid = [](const cv::Mat1f& disparity) {
    return std::count_if(disparity.begin(), disparity.end(), [](float d) { return isValidDisparity(d); });
  };
  ASSERT_EQ(runBinocular("--out " + path("plain.pfm")).exit_code, 0);
  const cv::Mat1f plain = readDisparityPfm(path("plain.pfm"));
  // Surfaces smaller than the whole image: nothing survives.
  std::ofstream(path("stereo.ini"), std::ios::app) << "[spike_removal]\nfilter = segmentation\nmin_region_pixels = "
                                                   << plain.total() + 1 << "\n";
  const CommandResult all_removed = runBinocular("--out " + path("none.pfm") + " --spike-removal");
  ASSERT_EQ(all_removed.exit_code, 0) << all_removed.output;
  EXPECT_NE(all_removed.output.find("spike removal"), std::string::npos) << all_removed.output;
  EXPECT_EQ(countValid(readDisparityPfm(path("none.pfm"))), 0);
  // Small surfaces (the speckles of a window matcher) go; what stays is unchanged and most of it.
  std::ofstream(path("stereo.ini")) << "[stereo]\nmax_disparity = 15\nuniqueness_threshold = 0.04\n"
                                       "[spike_removal]\nfilter = segmentation\nmin_region_pixels = 50\n";
  ASSERT_EQ(runBinocular("--out " + path("filtered.pfm") + " --spike-removal").exit_code, 0);
  const cv::Mat1f filtered = readDisparityPfm(path("filtered.pfm"));
  int changed = 0;
  for (size_t i = 0; i < plain.total(); ++i) {
    const float before = plain(static_cast<int>(i)), after = filtered(static_cast<int>(i));
    changed += isValidDisparity(after) && after != before;
  }
  EXPECT_EQ(changed, 0);
  EXPECT_LT(countValid(filtered), countValid(plain));
  EXPECT_GT(countValid(filtered), 0.8 * countValid(plain));
  // Without the flag the ini's section is not applied.
  ASSERT_EQ(runBinocular("--out " + path("again.pfm")).exit_code, 0);
  EXPECT_EQ(countValid(readDisparityPfm(path("again.pfm"))), countValid(plain));
}

TEST_F(DisparityCommandTest, GroundTruthScoresOnMasks) {
  const cv::Mat1f truth = loadMiddleburyGroundTruth(kData + "truedisp.row3.col3.pgm", 16.0);
  cv::Mat1b left_half(truth.size(), uchar{0});
  left_half.colRange(0, truth.cols / 2).setTo(255);
  left_half(100, 50) = 128;  // Middlebury's grey (occluded) is not evaluated
  ASSERT_TRUE(cv::imwrite(path("left.png"), left_half));
  const std::string gt = " --gt " + kData + "truedisp.row3.col3.pgm --gt-scale 16";
  const CommandResult result =
      runBinocular("--out " + path("out.pfm") + gt + " --gt-nonocc " + path("left.png") + " --gt-disc " + path("left.png") +
                   " --gt-border 10");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  int known_left = 0, known = 0;
  for (int y = 10; y < truth.rows - 10; ++y) {
    for (int x = 10; x < truth.cols - 10; ++x) {
      known += isValidDisparity(truth(y, x));
      known_left += isValidDisparity(truth(y, x)) && x < truth.cols / 2 && !(y == 100 && x == 50);
    }
  }
  const std::string counted = "(" + std::to_string(known_left) + " known pixels)";
  EXPECT_NE(result.output.find("evaluation nonocc: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("evaluation disc: "), std::string::npos) << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 4) << result.output;
  size_t masked_lines = 0;
  for (size_t at = result.output.find(counted); at != std::string::npos; at = result.output.find(counted, at + 1)) {
    ++masked_lines;
  }
  EXPECT_EQ(masked_lines, 2u) << result.output;
  EXPECT_NE(result.output.find("evaluation all: ", 0), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("(" + std::to_string(known) + " known pixels)"),
            std::string::npos)
      << result.output;

  // Without a mask the non-occluded pixels are derived from the truth (nonOccludedMask).
  const CommandResult derived = runBinocular("--out " + path("out.pfm") + gt);
  ASSERT_EQ(derived.exit_code, 0) << derived.output;
  EXPECT_NE(derived.output.find("evaluation nonocc (derived from the ground truth): "), std::string::npos)
      << derived.output;
}

TEST_F(DisparityCommandTest, MasksNeedGroundTruthAndTheirSize) {
  expectError(runBinocular("--out " + path("out.pfm") + " --gt-nonocc " + path("m.png")), 2, "need --gt");
  ASSERT_TRUE(cv::imwrite(path("small.png"), cv::Mat1b(10, 10, uchar{255})));
  expectError(runBinocular("--out " + path("out.pfm") + " --gt " + kData + "truedisp.row3.col3.pgm --gt-scale 16 --gt-disc " +
                           path("small.png")),
              1, "small.png: mask is 10x10");
}

TEST_F(DisparityCommandTest, MissingImageIsNamed) {
  expectError(run("--config " + path("stereo.ini") + " --ref " + path("nope.png") + " --cam " + kData +
                  "scene1.row3.col4.ppm:1:0 --out " + path("out.pfm")),
              1, "nope.png: no such image file");
}

TEST_F(DisparityCommandTest, ImagesOfDifferentSizesAreRejected) {
  const cv::Mat small = cv::imread(kData + "scene1.row3.col4.ppm")(cv::Rect(0, 0, 200, 150));
  ASSERT_TRUE(cv::imwrite(path("small.png"), small));
  expectError(run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " +
                  path("small.png") + ":1:0 --out " + path("out.pfm")),
              1, "small.png: image is 200x150");
}

TEST_F(DisparityCommandTest, GroundTruthOfAnotherSizeIsRejectedBeforeMatching) {
  const cv::Mat small = cv::imread(kData + "truedisp.row3.col3.pgm")(cv::Rect(0, 0, 200, 150));
  ASSERT_TRUE(cv::imwrite(path("gt.png"), small));
  expectError(runBinocular("--out " + path("out.pfm") + " --gt " + path("gt.png") + " --gt-scale 16"), 1,
              "gt.png: ground truth is 200x150");
}

TEST_F(DisparityCommandTest, MalformedCameraIsRejected) {
  expectError(run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
                  "scene1.row3.col4.ppm:1 --out " + path("out.pfm")),
              2, "expected IMAGE:BX:BY");
  expectError(run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
                  "scene1.row3.col4.ppm:one:0 --out " + path("out.pfm")),
              2, "expected IMAGE:BX:BY");
  expectError(run("--config " + path("stereo.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
                  "scene1.row3.col4.ppm:0:0 --out " + path("out.pfm")),
              2, "baseline (0, 0)");
}

TEST_F(DisparityCommandTest, MaxDisparityMustBePositiveAndBelowTheWidth) {
  expectError(runBinocular("--out " + path("out.pfm") + " --max-disp 0"), 2, "--max-disp: expected an integer in 1..4096, got '0'");
  expectError(runBinocular("--out " + path("out.pfm") + " --max-disp 384"), 2,
              "--max-disp 384: must be smaller than the image width 384");
}

TEST_F(DisparityCommandTest, WindowMustBeOddAndAtLeastThree) {
  expectError(runBinocular("--out " + path("out.pfm") + " --window 6"), 2, "--window 6: must be odd");
  expectError(runBinocular("--out " + path("out.pfm") + " --window 1"), 2, "--window: expected an integer in 3..255, got '1'");
}

TEST_F(DisparityCommandTest, UnknownIniKeyIsNamedWithTheNearestKnownKey) {
  std::ofstream(path("stereo.ini")) << "[stereo]\nmax_disparty = 15\n";
  expectError(runBinocular("--out " + path("out.pfm")), 1,
              "[stereo] unknown key 'max_disparty' (did you mean 'max_disparity'?)");
}

TEST_F(DisparityCommandTest, MissingConfigAndOutputTypeAreNamed) {
  expectError(run("--config " + path("none.ini") + " --ref " + kData + "scene1.row3.col3.ppm --cam " + kData +
                  "scene1.row3.col4.ppm:1:0 --out " + path("out.pfm")),
              1, "none.ini: cannot open the file");
  expectError(runBinocular("--out " + path("out.tiff")), 2, "--out");
}

}  // namespace
}  // namespace stereonav
