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
    directory_ = std::filesystem::temp_directory_path() /
                 ("stereonav_disparity_command_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(directory_);
    std::ofstream(path("stereo.ini")) << "# tsukuba: disparities 5..14\n[stereo]\nmax_disparity = 15\n"
                                         "uniqueness_threshold = 0.04\n";
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::string path(const std::string& name) const { return (directory_ / name).string(); }

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

  std::filesystem::path directory_;
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

TEST_F(DisparityCommandTest, MissingImageIsNamed) {
  expectError(run("--config " + path("stereo.ini") + " --ref " + path("nope.png") + " --cam " + kData +
                  "scene1.row3.col4.ppm:1:0 --out " + path("out.pfm")),
              1, "nope.png: cannot open image");
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
              1, "none.ini: cannot read config file");
  expectError(runBinocular("--out " + path("out.tiff")), 2, "--out");
}

}  // namespace
}  // namespace stereonav
