#include "disparity/sad_matcher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "disparity/prefilter.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::rectMask;
using testing::shareCorrect;
using testing::SyntheticScene;

const cv::Size kSize(120, 90);
const cv::Rect kPlane(45, 30, 40, 35);  // a near plane in front of the background

StereoOptions matchOptions() {
  StereoOptions options;
  options.min_disparity = 0;
  options.max_disparity = 15;
  options.window = 7;
  return options;
}

StereoFrame renderFrame(SyntheticScene& scene, const std::vector<SecondaryCamera>& cameras) {
  StereoFrame frame;
  frame.reference = scene.view(0, 0);
  for (const SecondaryCamera& camera : cameras) frame.secondaries.push_back({scene.view(camera.bx, camera.by), camera});
  return frame;
}

// Pixels at least `gap` away from the plane's outline (inside and outside) and from the image border
// plus `border`: there every camera sees the same surface as the reference, through the whole window.
cv::Mat1b awayFromEdges(int gap, int border) {
  cv::Mat1b mask = rectMask(kSize, cv::Rect(border, border, kSize.width - 2 * border, kSize.height - 2 * border));
  const cv::Rect outline(kPlane.x - gap, kPlane.y - gap, kPlane.width + 2 * gap, kPlane.height + 2 * gap);
  const cv::Rect inner(kPlane.x + gap, kPlane.y + gap, kPlane.width - 2 * gap, kPlane.height - 2 * gap);
  mask(outline & cv::Rect(cv::Point(), kSize)).setTo(0);
  mask(inner).setTo(255);
  return mask;
}

struct RigCase {
  const char* name;
  std::vector<SecondaryCamera> cameras;
  int border;  // columns on the side(s) where candidates leave the image, plus the window
};

class PlanesAtKnownDisparityTest : public ::testing::TestWithParam<RigCase> {};

TEST_P(PlanesAtKnownDisparityTest, FindsBothPlanes) {
  SyntheticScene scene(kSize, 4.0, 7);
  scene.addPlane(kPlane, 10.0);
  const StereoFrame frame = renderFrame(scene, GetParam().cameras);
  const SadMatch match = SadMatcher(matchOptions()).match(frame);
  // Occlusions reach 2 * (10 - 4) pixels from the plane's outline for the longest baselines.
  EXPECT_GE(shareCorrect(match.disparity, scene.trueDisparity(), awayFromEdges(16, GetParam().border)), 0.99)
      << GetParam().name;
  EXPECT_DOUBLE_EQ(match.disparity(kPlane.y + 17, kPlane.x + 20), 10.0) << GetParam().name;
  EXPECT_DOUBLE_EQ(match.disparity(20, 35), 4.0) << GetParam().name;
}

INSTANTIATE_TEST_SUITE_P(
    Rigs, PlanesAtKnownDisparityTest,
    ::testing::Values(RigCase{"binocular right", {{1, 0}}, 18}, RigCase{"binocular left", {{-1, 0}}, 18},
                      RigCase{"top camera", {{0, -1}}, 18}, RigCase{"bottom camera", {{0, 1}}, 18},
                      RigCase{"triclops L", {{-1, 0}, {0, -1}}, 18},
                      RigCase{"middlebury collinear", {{-2, 0}, {-1, 0}, {1, 0}, {2, 0}}, 18},
                      RigCase{"double baseline", {{2, 0}}, 33}, RigCase{"half baseline", {{0.5, 0}}, 11},
                      RigCase{"diagonal", {{1, 1}}, 18}),
    [](const auto& info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    });

TEST(SadMatcherTest, HalfBaselineInterpolatesHalfPixelShifts) {
  // With a 0.5 baseline, odd disparities shift the secondary view by half pixels. On raw grey
  // levels linear interpolation finds them exactly; after the x-Sobel prefilter, which amplifies
  // the interpolation's smoothing, within one disparity (half a pixel in the secondary image).
  SyntheticScene scene(kSize, 5.0, 3);
  scene.addPlane(kPlane, 11.0);
  const StereoFrame frame = renderFrame(scene, {{0.5, 0}});
  StereoOptions options = matchOptions();
  EXPECT_GE(shareCorrect(SadMatcher(options).match(frame).disparity, scene.trueDisparity(), awayFromEdges(8, 12), 1.0), 0.99);
  options.prefilter = Prefilter::kNone;
  EXPECT_GE(shareCorrect(SadMatcher(options).match(frame).disparity, scene.trueDisparity(), awayFromEdges(8, 12)), 0.99);
}

TEST(SadMatcherTest, SubpixelRefinementRecoversFractionalDisparity) {
  SyntheticScene scene(kSize, 6.5, 5);
  const StereoFrame frame = renderFrame(scene, {{1, 0}});
  StereoOptions options = matchOptions();
  const cv::Mat1b interior = rectMask(kSize, cv::Rect(25, 10, 80, 70));
  const SadMatch whole = SadMatcher(options).match(frame);
  options.subpixel = true;
  const SadMatch refined = SadMatcher(options).match(frame);
  double whole_error = 0.0, refined_error = 0.0;
  for (int y = 10; y < 80; ++y) {
    for (int x = 25; x < 105; ++x) {
      whole_error += std::abs(whole.disparity(y, x) - 6.5);
      refined_error += std::abs(refined.disparity(y, x) - 6.5);
    }
  }
  const double pixels = cv::countNonZero(interior);
  EXPECT_GE(whole_error / pixels, 0.5);  // integer disparities are at least half a pixel off
  EXPECT_LT(refined_error / pixels, 0.2);
}

// The sampling interval of Birchfield and Tomasi at pixel (x, y) along (dx, dy): the lowest and
// highest of its value and the values halfway (rounded up) to its two neighbours along it.
std::pair<int, int> samplingInterval(const cv::Mat1b& image, int x, int y, int dx, int dy) {
  const auto pixel = [&](int px, int py) {
    return static_cast<int>(image(std::clamp(py, 0, image.rows - 1), std::clamp(px, 0, image.cols - 1)));
  };
  const int value = pixel(x, y);
  const int before = (value + pixel(x - dx, y - dy) + 1) / 2, after = (value + pixel(x + dx, y + dy) + 1) / 2;
  return {std::min({value, before, after}), std::max({value, before, after})};
}

// The SAD (or the sum of Birchfield-Tomasi costs) of camera c over the window at reference pixel
// (x, y) and disparity d; pixels off the image repeat the nearest border pixel, as the engine pads
// its images.
int windowSad(const std::vector<cv::Mat1b>& images, const std::vector<SecondaryCamera>& cameras, size_t c, int window,
              int x, int y, int d, PixelCost cost = PixelCost::kAbsoluteDifference) {
  const auto clamped = [](const cv::Mat1b& image, int px, int py) {
    return cv::Point(std::clamp(px, 0, image.cols - 1), std::clamp(py, 0, image.rows - 1));
  };
  const int bx = static_cast<int>(cameras[c].bx), by = static_cast<int>(cameras[c].by);
  const int dx = (bx > 0) - (bx < 0), dy = (by > 0) - (by < 0);  // the baseline's direction
  const int r = window / 2;
  int sad = 0;
  for (int wy = -r; wy <= r; ++wy) {
    for (int wx = -r; wx <= r; ++wx) {
      const cv::Point p = clamped(images[0], x + wx, y + wy);
      const cv::Point q = clamped(images[c + 1], x + wx - bx * d, y + wy - by * d);
      const int reference = images[0](p), candidate = images[c + 1](q);
      if (cost == PixelCost::kAbsoluteDifference) {
        sad += std::abs(reference - candidate);
        continue;
      }
      const auto [candidate_low, candidate_high] = samplingInterval(images[c + 1], q.x, q.y, dx, dy);
      const int to_candidate = std::max({0, reference - candidate_high, candidate_low - reference});
      if (cost == PixelCost::kBirchfieldTomasiOneSided) {
        sad += to_candidate;
        continue;
      }
      const auto [reference_low, reference_high] = samplingInterval(images[0], p.x, p.y, dx, dy);
      const int to_reference = std::max({0, candidate - reference_high, reference_low - candidate});
      sad += std::min(to_candidate, to_reference);
    }
  }
  return sad;
}

// The images of each cost channel, the views in the same order: the views prefiltered as
// `options` says, and with the intensity term their grey levels at a quarter scale, rounded half
// up.
using Channels = std::vector<std::vector<cv::Mat1b>>;

Channels channelImages(const std::vector<cv::Mat1b>& views, const StereoOptions& options) {
  Channels channels(options.intensity_term ? 2 : 1);
  for (const cv::Mat1b& view : views) {
    cv::Mat1b filtered;
    prefilterImage(view, options.prefilter, options.prefilter_cap, options.texture_sigma, filtered);
    channels[0].push_back(filtered);
    if (!options.intensity_term) continue;
    cv::Mat1b quarter(view.size());
    for (int y = 0; y < view.rows; ++y) {
      for (int x = 0; x < view.cols; ++x) quarter(y, x) = static_cast<uchar>((view(y, x) + 2) / 4);
    }
    channels[1].push_back(quarter);
  }
  return channels;
}

// Camera c's window cost: its windowSad summed over the channels.
int cameraCost(const Channels& channels, const std::vector<SecondaryCamera>& cameras, size_t c,
               const StereoOptions& options, int x, int y, int d) {
  int cost = 0;
  for (const std::vector<cv::Mat1b>& images : channels) {
    cost += windowSad(images, cameras, c, options.window, x, y, d, options.pixel_cost);
  }
  return cost;
}

// Window scores computed the slow way: per candidate, per camera, the cost of the channels over
// the window, combined by sum or by the ceil(N/2) lowest.
struct BruteForce {
  int best_score;
  int score_sum;
  int best_disparity;
  int second_score;  // lowest score more than one disparity from the best
};

BruteForce bruteForce(const Channels& channels, const std::vector<SecondaryCamera>& cameras,
                      const StereoOptions& options, int x, int y, bool best_half) {
  BruteForce result{1 << 30, 0, -1, std::numeric_limits<int>::max()};
  std::vector<int> scores;
  for (int d = options.min_disparity; d <= options.max_disparity; ++d) {
    std::vector<int> per_camera;
    for (size_t c = 0; c < cameras.size(); ++c) {
      per_camera.push_back(cameraCost(channels, cameras, c, options, x, y, d));
    }
    std::sort(per_camera.begin(), per_camera.end());
    const size_t kept = best_half ? (per_camera.size() + 1) / 2 : per_camera.size();
    int score = 0;
    for (size_t k = 0; k < kept; ++k) score += per_camera[k];
    result.score_sum += score;
    scores.push_back(score);
    if (score < result.best_score) {
      result.best_score = score;
      result.best_disparity = d;
    }
  }
  for (size_t j = 0; j < scores.size(); ++j) {
    if (std::abs(options.min_disparity + static_cast<int>(j) - result.best_disparity) > 1) {
      result.second_score = std::min(result.second_score, scores[j]);
    }
  }
  return result;
}

// A frame of uniform noise for every camera; `images` receives the reference, then the secondaries.
StereoFrame noiseFrame(const std::vector<SecondaryCamera>& cameras, cv::Size size, uint64_t seed,
                       std::vector<cv::Mat1b>& images) {
  cv::RNG rng(seed);
  StereoFrame frame;
  frame.reference.create(size);
  rng.fill(frame.reference, cv::RNG::UNIFORM, 0, 256);
  images = {frame.reference};
  for (const SecondaryCamera& camera : cameras) {
    cv::Mat1b image(size);
    rng.fill(image, cv::RNG::UNIFORM, 0, 256);
    frame.secondaries.push_back({image, camera});
    images.push_back(image);
  }
  return frame;
}

// The matcher's scores against the brute-force ones at a few points; with a prefilter, the brute
// force sums the differences of the prefiltered images (raw grey levels by default).
void expectMatchesBruteForce(const std::vector<SecondaryCamera>& cameras, StereoOptions options,
                             Prefilter prefilter = Prefilter::kNone) {
  std::vector<cv::Mat1b> images;
  const StereoFrame frame = noiseFrame(cameras, cv::Size(80, 60), 11, images);
  options.prefilter = prefilter;
  options.second_best_ratio = 0.9;  // so that the runner-up is found
  const Channels channels = channelImages(images, options);
  const SadMatch match = SadMatcher(options).match(frame);
  const bool best_half = options.combination == CameraCombination::kBestHalf;
  SCOPED_TRACE(::testing::Message() << cameras.size() << " camera(s), first (" << cameras[0].bx << ", "
                                    << cameras[0].by << "), window " << options.window);
  // Points where every camera of the cases below sees every candidate.
  for (const cv::Point& p : {cv::Point(40, 30), cv::Point(38, 40), cv::Point(45, 25)}) {
    const BruteForce expected = bruteForce(channels, cameras, options, p.x, p.y, best_half);
    EXPECT_EQ(match.best_score(p), expected.best_score) << p;
    EXPECT_EQ(match.score_sum(p), expected.score_sum) << p;
    EXPECT_EQ(match.disparity(p), expected.best_disparity) << p;
    EXPECT_EQ(match.second_score(p), expected.second_score) << p;
  }
}

TEST(SadMatcherTest, NoRunnerUpWithoutTheDistinctivenessTest) {
  StereoFrame frame{cv::Mat1b(40, 60, uchar{7}), {{cv::Mat1b(40, 60, uchar{9}), {1, 0}}}};
  EXPECT_TRUE(SadMatcher(matchOptions()).match(frame).second_score.empty());
}

// The reverse disparity, read from the reference's window scores, is what matching again with
// the secondary camera as the reference finds, wherever that match sees all its candidates.
void expectReverseMatchesSwappedMatch(const SecondaryCamera& camera) {
  cv::RNG rng(5);
  cv::Mat1b reference(50, 90), secondary(50, 90);
  rng.fill(reference, cv::RNG::UNIFORM, 0, 256);
  rng.fill(secondary, cv::RNG::UNIFORM, 0, 256);
  const StereoFrame frame{reference, {{secondary, camera}}};
  StereoOptions options = matchOptions();
  options.max_disparity = 20;
  options.left_right_check = true;
  const SadMatch reverse = SadMatcher(options).match(frame);
  options.left_right_check = false;
  const SadMatch swapped = SadMatcher(options).match(swapReferenceWithFirstSecondary(frame));
  ASSERT_FALSE(reverse.reverse_disparity.empty());
  int compared = 0;
  for (int y = 3; y < 47; ++y) {
    for (int x = 3 + options.max_disparity; x < 87 - options.max_disparity; ++x) {
      EXPECT_EQ(reverse.reverse_disparity(y, x), swapped.disparity(y, x)) << "(" << x << ", " << y << ")";
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(SadMatcherTest, ReverseDisparityEqualsTheSwappedMatchRightCamera) { expectReverseMatchesSwappedMatch({1, 0}); }

TEST(SadMatcherTest, ReverseDisparityEqualsTheSwappedMatchLeftCamera) { expectReverseMatchesSwappedMatch({-1, 0}); }

TEST(SadMatcherTest, NoReverseDisparityForSeveralCameras) {
  const cv::Mat1b image(40, 60, uchar{7});
  StereoOptions options = matchOptions();
  options.left_right_check = true;
  EXPECT_TRUE(SadMatcher(options).match({image, {{image, {1, 0}}, {image, {0, 1}}}}).reverse_disparity.empty());
}

TEST(SadMatcherTest, ScoresEqualPlainSadOneCamera) {
  expectMatchesBruteForce({{1, 0}}, matchOptions());
}

TEST(SadMatcherTest, ScoresEqualSumOfCameraSads) {
  StereoOptions options = matchOptions();
  options.max_disparity = 12;  // 13 candidates: the last vector is partly padding
  expectMatchesBruteForce({{-1, 0}, {0, -1}, {1, 0}}, options);
}

// x-Sobel differences are at most 62: those of up to four cameras add up within a byte, which
// the loop uses to widen them once.
TEST(SadMatcherTest, ScoresEqualSumOfCameraSadsOfThePrefilteredImages) {
  expectMatchesBruteForce({{-1, 0}, {0, -1}}, matchOptions(), Prefilter::kXSobel);  // the Triclops L
  expectMatchesBruteForce({{-1, 0}, {0, -1}, {1, 0}}, matchOptions(), Prefilter::kXSobel);
  expectMatchesBruteForce({{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}, matchOptions(), Prefilter::kXSobel);
}

TEST(SadMatcherTest, ScoresEqualPlainSadDiagonalCameras) {
  expectMatchesBruteForce({{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}, matchOptions());
}

TEST(SadMatcherTest, WideAccumulatorsWhenSixteenBitsCouldOverflow) {
  StereoOptions options = matchOptions();
  options.window = 15;  // 225 * 255 * 2 cameras > 65535
  options.max_disparity = 10;
  expectMatchesBruteForce({{1, 0}, {0, 1}}, options);
}

TEST(SadMatcherTest, BestHalfKeepsTheLowestCameraScores) {
  StereoOptions options = matchOptions();
  options.combination = CameraCombination::kBestHalf;
  expectMatchesBruteForce({{-2, 0}, {-1, 0}, {1, 0}, {2, 0}}, options);
}

TEST(SadMatcherTest, MinimumDisparityOffsetsTheSearch) {
  StereoOptions options = matchOptions();
  options.min_disparity = 3;
  options.max_disparity = 20;
  expectMatchesBruteForce({{1, 0}}, options);
}

// Cameras on each axis and diagonal, interpolated ones (baselines of 2), byte sums of prefiltered
// images, 32-bit scores and best half: the Birchfield-Tomasi costs, symmetric and one-sided, the
// slow way.
void expectBirchfieldTomasiMatchesBruteForce(PixelCost cost) {
  StereoOptions options = matchOptions();
  options.pixel_cost = cost;
  expectMatchesBruteForce({{1, 0}}, options);
  expectMatchesBruteForce({{-1, 0}, {0, -1}, {0, 1}}, options, Prefilter::kXSobel);
  expectMatchesBruteForce({{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}, options);
  options.combination = CameraCombination::kBestHalf;
  expectMatchesBruteForce({{-2, 0}, {-1, 0}, {1, 0}, {2, 0}}, options);
  options.combination = CameraCombination::kSum;
  options.window = 15;
  options.max_disparity = 10;
  expectMatchesBruteForce({{1, 0}, {0, 1}}, options);
}

TEST(SadMatcherTest, BirchfieldTomasiScoresEqualTheSlowWay) {
  expectBirchfieldTomasiMatchesBruteForce(PixelCost::kBirchfieldTomasi);
}

TEST(SadMatcherTest, OneSidedBirchfieldTomasiScoresEqualTheSlowWay) {
  expectBirchfieldTomasiMatchesBruteForce(PixelCost::kBirchfieldTomasiOneSided);
}

// A surface sampled half a pixel apart in the two images: between samples a piecewise-linear
// image is exactly the average of its neighbours, so Birchfield-Tomasi (either way: the reference
// samples fall inside the candidates' intervals) finds no difference at the true match, while SAD
// pays half the local slope at every pixel.
TEST(SadMatcherTest, BirchfieldTomasiForgivesHalfPixelSampling) {
  constexpr int kWidth = 120, kHeight = 30;
  cv::RNG rng(8);
  // A row of linear pieces of random slopes and lengths, at twice the image resolution.
  std::vector<int> fine(2 * kWidth + 20);
  int value = 128, slope = 0;
  for (size_t i = 0; i < fine.size(); ++i) {
    if (i % 2 == 0 && rng.uniform(0, 8) == 0) slope = rng.uniform(-6, 7);
    value = std::clamp(value + slope, 0, 255);
    if (value == 0 || value == 255) slope = -slope;
    fine[i] = value;
  }
  cv::Mat1b reference(kHeight, kWidth), secondary(kHeight, kWidth);
  for (int x = 0; x < kWidth; ++x) {
    reference.col(x).setTo(fine[2 * x]);  // secondary(x - 4.5) = reference(x)
    secondary.col(x).setTo(fine[2 * x + 9]);
  }
  StereoOptions options = matchOptions();
  options.prefilter = Prefilter::kNone;
  options.window = 5;
  options.left_right_check = false;
  const StereoFrame frame{reference, {{secondary, {1, 0}}}};
  const SadMatch sad = SadMatcher(options).match(frame);
  const cv::Rect interior(20, 5, 90, 20);
  const double sad_score = cv::mean(sad.best_score(interior))[0];
  EXPECT_GT(sad_score, 10.0);
  for (PixelCost cost : {PixelCost::kBirchfieldTomasi, PixelCost::kBirchfieldTomasiOneSided}) {
    options.pixel_cost = cost;
    const SadMatch birchfield_tomasi = SadMatcher(options).match(frame);
    EXPECT_LT(cv::mean(birchfield_tomasi.best_score(interior))[0], 0.25 * sad_score);
  }
}

TEST(SadMatcherTest, BestHalfMatchesOccludedStripsThatTheSumGetsWrong) {
  // Left of the plane, a strip of background is hidden from the cameras on the right (bx > 0);
  // right of it, from those on the left. The cameras on the other side still see it.
  SyntheticScene scene(kSize, 3.0, 9);
  scene.addPlane(kPlane, 9.0);
  const StereoFrame frame = renderFrame(scene, {{-2, 0}, {-1, 0}, {1, 0}, {2, 0}});
  // The 6 (= 9 - 3) columns next to the plane are hidden from both cameras on one side.
  cv::Mat1b strips = rectMask(kSize, cv::Rect(kPlane.x - 6, kPlane.y + 4, 6, kPlane.height - 8));
  strips(cv::Rect(kPlane.br().x, kPlane.y + 4, 6, kPlane.height - 8)).setTo(255);
  StereoOptions options = matchOptions();
  const double sum_correct = shareCorrect(SadMatcher(options).match(frame).disparity, scene.trueDisparity(), strips);
  options.combination = CameraCombination::kBestHalf;
  const double best_half_correct = shareCorrect(SadMatcher(options).match(frame).disparity, scene.trueDisparity(), strips);
  // Pixels whose window straddles the plane's edge stay hard for both (about 0.73 vs 0.82 here).
  EXPECT_GT(best_half_correct, sum_correct + 0.05);
  EXPECT_GT(best_half_correct, 0.75);
}

TEST(SadMatcherTest, BordersUseTheCamerasThatStillSeeEveryCandidate) {
  SyntheticScene scene(kSize, 6.0, 13);
  const StereoFrame frame = renderFrame(scene, {{-1, 0}, {0, -1}});  // Triclops L: left and top
  const SadMatch match = SadMatcher(matchOptions()).match(frame);
  const cv::Mat1f truth = scene.trueDisparity();
  const int w = kSize.width, h = kSize.height, max_d = 15;
  // Right strip: the left camera's candidates leave the image, the top camera's do not.
  EXPECT_GE(shareCorrect(match.disparity, truth, rectMask(kSize, cv::Rect(w - max_d, 10, max_d - 3, h - max_d - 20))), 0.99);
  // Bottom strip: only the left camera.
  EXPECT_GE(shareCorrect(match.disparity, truth, rectMask(kSize, cv::Rect(10, h - max_d, w - max_d - 20, max_d - 3))), 0.99);
  // Bottom-right corner: no camera sees all candidates.
  EXPECT_EQ(testing::shareInvalid(match.disparity, rectMask(kSize, cv::Rect(w - max_d, h - max_d, max_d, max_d))), 1.0);
}

TEST(SadMatcherTest, CalibrationRoundingOffAUnitBaselineMatchesTheUnitBaseline) {
  // A rawlog's camera poses give baselines like (-4.6e-32, -0.99999999999999978) for a top
  // camera: every candidate still lands exactly on the pixel of the unit baseline.
  SyntheticScene scene(kSize, 4.0, 19);
  scene.addPlane(kPlane, 10.0);
  const StereoFrame exact = renderFrame(scene, {{-1, 0}, {0, -1}});
  StereoFrame rounded = exact;
  rounded.secondaries[1].camera = {-4.5554407119658594e-32, -0.99999999999999978};
  const SadMatch a = SadMatcher(matchOptions()).match(exact);
  const SadMatch b = SadMatcher(matchOptions()).match(rounded);
  const cv::Rect interior(0, 0, kSize.width - 1, kSize.height);  // (x = w-1 is a border case for b)
  EXPECT_EQ(cv::norm(a.best_score(interior), b.best_score(interior), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.score_sum(interior), b.score_sum(interior), cv::NORM_INF), 0.0);
}

// One step of a path (Hirschmuller 2008, eq. 13): the pixel's cost plus the cheapest way to reach
// each candidate from the path at the neighbour before it, less that path's lowest entry, at most
// `cap`; without a neighbour (`previous` null) the path starts at the pixel.
std::vector<long long> pathStep(const std::vector<long long>& cost, const std::vector<long long>* previous,
                                long long p1, long long p2, long long cap) {
  if (!previous) return cost;
  const long long lowest = *std::min_element(previous->begin(), previous->end());
  const int candidates = static_cast<int>(cost.size());
  std::vector<long long> result(candidates);
  for (int j = 0; j < candidates; ++j) {
    long long reach = std::min((*previous)[j], lowest + p2);
    if (j > 0) reach = std::min(reach, (*previous)[j - 1] + p1);
    if (j + 1 < candidates) reach = std::min(reach, (*previous)[j + 1] + p1);
    result[j] = std::min(cost[j] + reach - lowest, cap);
  }
  return result;
}

// The aggregated scores computed the slow way over reference columns [x0, x1) and every row (one
// match region): the window SAD of every candidate (borders replicated, as the engine pads), the
// paths from the left and from the right along each row and, for the semi-global aggregation, the
// paths from the upper left, from above and from the upper right, each restarting at the region's
// edges; their sum, as totals[y][x - x0][candidate]. Where the scanline's paths are bytes
// (scanlinePathShift), the window scores and jump costs are divided by 2^shift and every path
// value and sum stops at 255.
std::vector<std::vector<std::vector<long long>>> bruteForceAggregation(const Channels& channels,
                                                                       const std::vector<SecondaryCamera>& cameras,
                                                                       const StereoOptions& options, int x0, int x1) {
  using Paths = std::vector<std::vector<long long>>;  // [column][candidate]
  const int candidates = options.disparityCount();
  const int columns = x1 - x0, rows = channels[0][0].rows;
  const long long scale = static_cast<long long>(options.window) * options.window * static_cast<long long>(cameras.size());
  const int shift = scanlinePathShift(options, static_cast<int>(cameras.size()));
  const long long cap = shift >= 0 ? 255 : std::numeric_limits<long long>::max();
  const double jump_scale = std::ldexp(static_cast<double>(scale), shift >= 0 ? -shift : 0);
  const long long p1 = std::llround(options.scanline_p1 * jump_scale), p2 = std::llround(options.scanline_p2 * jump_scale);
  std::vector<Paths> totals(rows, Paths(columns, std::vector<long long>(candidates, 0)));
  Paths from_above[3];  // the previous row's paths from the upper left, above and the upper right
  for (int y = 0; y < rows; ++y) {
    Paths cost(columns, std::vector<long long>(candidates, 0));
    for (int i = 0; i < columns; ++i) {
      for (int j = 0; j < candidates; ++j) {
        for (size_t c = 0; c < cameras.size(); ++c) {
          cost[i][j] += cameraCost(channels, cameras, c, options, x0 + i, y, options.min_disparity + j);
        }
        if (shift >= 0) cost[i][j] = std::min(cost[i][j] >> shift, cap);
      }
    }
    std::vector<Paths> paths;
    for (const int direction : {1, -1}) {
      Paths path(columns);
      for (int step = 0; step < columns; ++step) {
        const int i = direction > 0 ? step : columns - 1 - step;
        path[i] = pathStep(cost[i], step == 0 ? nullptr : &path[i - direction], p1, p2, cap);
      }
      paths.push_back(path);
    }
    if (options.aggregation == CostAggregation::kSemiGlobal) {
      for (int direction = 0; direction < 3; ++direction) {
        Paths path(columns);
        for (int i = 0; i < columns; ++i) {
          const int from = i + direction - 1;
          const bool starts = y == 0 || from < 0 || from >= columns;
          path[i] = pathStep(cost[i], starts ? nullptr : &from_above[direction][from], p1, p2, cap);
        }
        paths.push_back(path);
        from_above[direction] = path;
      }
    }
    for (const Paths& path : paths) {
      for (int i = 0; i < columns; ++i) {
        for (int j = 0; j < candidates; ++j) totals[y][i][j] = std::min(totals[y][i][j] + path[i][j], cap);
      }
    }
  }
  return totals;
}

// The winner-takes-all of one pixel's aggregated scores: the lowest, its smallest disparity, the
// runner-up more than one disparity away and the sum.
BruteForce decideBruteForce(const std::vector<long long>& total, const StereoOptions& options) {
  BruteForce result{std::numeric_limits<int>::max(), 0, -1, std::numeric_limits<int>::max()};
  const int candidates = static_cast<int>(total.size());
  for (int j = 0; j < candidates; ++j) {
    result.score_sum += static_cast<int>(total[j]);
    if (total[j] < result.best_score) {
      result.best_score = static_cast<int>(total[j]);
      result.best_disparity = options.min_disparity + j;
    }
  }
  for (int j = 0; j < candidates; ++j) {
    if (std::abs(options.min_disparity + j - result.best_disparity) > 1) {
      result.second_score = std::min(result.second_score, static_cast<int>(total[j]));
    }
  }
  return result;
}

// `options.aggregation` (scanline or semi-global) against bruteForceAggregation, on the images
// prefiltered by `prefilter` (raw grey levels by default). With partial_candidates, the pixels
// whose best candidate is off the secondary image have no disparity.
void expectPathsMatchBruteForce(const std::vector<SecondaryCamera>& cameras, StereoOptions options, int x0, int x1,
                                Prefilter prefilter = Prefilter::kNone) {
  std::vector<cv::Mat1b> images;
  const StereoFrame frame = noiseFrame(cameras, cv::Size(std::max(70, x1), 30), 23, images);
  options.prefilter = prefilter;
  options.second_best_ratio = 0.9;      // so that the runner-up is found
  options.uniqueness_threshold = 0.5;   // and the sum of scores
  // One camera on the row: the left-right check reads the reverse match from the aggregated scores.
  options.left_right_check = cameras.size() == 1;
  const SadMatch match = SadMatcher(options).match(frame);
  const auto totals = bruteForceAggregation(channelImages(images, options), cameras, options, x0, x1);
  const int width = images[0].cols;
  for (const int y : {0, 14, 29}) {
    for (int x = x0; x < x1; ++x) {
      const BruteForce pixel = decideBruteForce(totals[y][x - x0], options);
      const int sample = x - static_cast<int>(cameras[0].bx) * pixel.best_disparity;
      const bool off_image = sample < 0 || sample >= width;
      ASSERT_EQ(match.best_score(y, x), pixel.best_score) << "(" << x << ", " << y << ")";
      ASSERT_EQ(match.disparity(y, x), off_image ? kInvalidDisparity : pixel.best_disparity)
          << "(" << x << ", " << y << ")";
      ASSERT_EQ(match.second_score(y, x), pixel.second_score) << "(" << x << ", " << y << ")";
      ASSERT_EQ(match.score_sum(y, x), pixel.score_sum) << "(" << x << ", " << y << ")";
    }
    if (!options.left_right_check) continue;
    // Secondary pixel s is reached by candidate d of reference pixel s + bx * d: the lowest such
    // aggregated score, the smallest disparity on ties; none where byte paths saturated at all of
    // them.
    const bool byte_paths = scanlinePathShift(options, static_cast<int>(cameras.size())) >= 0;
    const int bx = static_cast<int>(cameras[0].bx);
    int compared = 0;
    for (int s = 0; s < images[1].cols; ++s) {
      long long lowest = std::numeric_limits<long long>::max();
      float disparity = kInvalidDisparity;
      for (int d = options.min_disparity; d <= options.max_disparity; ++d) {
        const int x = s + bx * d;
        if (x < x0 || x >= x1) continue;
        const long long total = totals[y][x - x0][d - options.min_disparity];
        if (total < lowest) {
          lowest = total;
          disparity = static_cast<float>(d);
        }
      }
      if (byte_paths && lowest == 255) disparity = kInvalidDisparity;
      ASSERT_EQ(match.reverse_disparity(y, s), disparity) << "(" << s << ", " << y << ")";
      compared += disparity != kInvalidDisparity;
    }
    EXPECT_GT(compared, 40);
  }
}

// A 3x3 window, 13 candidates (the last vector partly padding) and jump costs of 2 and 9: the
// scores of the scanline's two paths and of the five semi-global ones fit 16 bits.
StereoOptions smallPathOptions(CostAggregation aggregation) {
  StereoOptions options = matchOptions();
  options.window = 3;
  options.max_disparity = 12;
  options.scanline_p1 = 2;
  options.scanline_p2 = 9;
  options.aggregation = aggregation;
  return options;
}

TEST(SadMatcherTest, ScanlineEqualsThePathsComputedTheSlowWay) {
  const StereoOptions options = smallPathOptions(CostAggregation::kScanline);
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70);
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 58);
}

// The matcher keeps the scanline's byte paths in registers from pixel to pixel when they are two
// vectors, in memory otherwise: 13, 20, 40, 70 and 150 candidates are 1, 1, 2, 3 and 5 vectors of
// bytes with AVX2 (1, 2, 3, 5 and 10 with SSE2). The semi-global paths (16-bit) stay in memory.
TEST(SadMatcherTest, PathsEqualTheSlowWayAtEveryVectorCount) {
  for (const SimdLevel simd : {SimdLevel::kSse2, SimdLevel::kAvx2}) {
    if (!simdSupported(simd)) continue;
    for (const CostAggregation aggregation : {CostAggregation::kScanline, CostAggregation::kSemiGlobal}) {
      for (const int candidates : {13, 20, 40, 70, 150}) {
        StereoOptions options = smallPathOptions(aggregation);
        options.simd = simd;
        options.max_disparity = candidates - 1;
        SCOPED_TRACE(std::to_string(candidates) + " candidates, SIMD level " + std::to_string(static_cast<int>(simd)));
        expectPathsMatchBruteForce({{1, 0}}, options, candidates - 1, candidates + 59);
      }
    }
  }
}

TEST(SadMatcherTest, ScanlineEqualsTheSlowWayWithSeveralCamerasAndWideScores) {
  StereoOptions options = matchOptions();
  options.min_disparity = 2;
  options.max_disparity = 20;  // 19 candidates
  options.window = 7;          // grey levels: 49 * 255 * 2 < 32767, byte paths, scores divided by 2^6
  options.aggregation = CostAggregation::kScanline;
  options.prefilter = Prefilter::kNone;  // as expectPathsMatchBruteForce matches
  ASSERT_EQ(scanlinePathShift(options, 2), 6);
  // Columns where both cameras see every candidate: one region, its paths restart at its ends.
  expectPathsMatchBruteForce({{1, 0}, {-1, 0}}, options, 20, 50);
  options.window = 15;  // 225 * 255 * 2 > 32767: 32-bit window scores and paths
  ASSERT_EQ(scanlinePathShift(options, 2), -1);
  expectPathsMatchBruteForce({{1, 0}, {-1, 0}}, options, 20, 50);
}

// The byte paths' scale from the largest window score, by hand: 5x5 x-Sobel capped at 31 (62 per
// pixel) with the grey levels at a quarter scale (64): 25 * 126 = 3150 per camera. One camera:
// 3150 / 8 = 393 < 512, so 2^3, and the large jump 32 * 25 / 8 = 100. Four cameras: 12600 / 32.
// Semi-global paths, more than 256 candidates, or a large jump above 255 keep 16-bit paths.
TEST(SadMatcherTest, BytePathsScaleTheLargestWindowScoreUnder512) {
  StereoOptions options;
  options.window = 5;
  options.prefilter = Prefilter::kXSobel;
  options.prefilter_cap = 31;
  options.intensity_term = true;
  options.aggregation = CostAggregation::kScanline;
  options.max_disparity = 63;
  EXPECT_EQ(scanlinePathShift(options, 1), 3);
  EXPECT_EQ(scanlinePathShift(options, 4), 5);
  options.intensity_term = false;  // 25 * 62 = 1550: 1550 / 4 = 387
  EXPECT_EQ(scanlinePathShift(options, 1), 2);
  options.max_disparity = 255;  // 256 candidates: indices still fit a byte
  EXPECT_EQ(scanlinePathShift(options, 1), 2);
  options.max_disparity = 256;
  EXPECT_EQ(scanlinePathShift(options, 1), -1);
  options.max_disparity = 63;
  options.scanline_p2 = 48;  // 48 * 25 / 4 = 300 > 255
  EXPECT_EQ(scanlinePathShift(options, 1), -1);
  options.scanline_p2 = 32;
  options.aggregation = CostAggregation::kSemiGlobal;
  EXPECT_EQ(scanlinePathShift(options, 1), -1);
}

TEST(SadMatcherTest, SemiGlobalEqualsTheFivePathsComputedTheSlowWay) {
  StereoOptions options = smallPathOptions(CostAggregation::kSemiGlobal);
  options.threads = 3;  // the paths from above still run down the whole image
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70);
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 58);
  options.window = 5;  // 5 * (25 * 255 + 9 * 25) > 32767: 32-bit scores
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70);
}

TEST(SadMatcherTest, BirchfieldTomasiWithSemiGlobalPathsEqualsTheSlowWay) {
  StereoOptions options = smallPathOptions(CostAggregation::kSemiGlobal);
  options.pixel_cost = PixelCost::kBirchfieldTomasi;
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70);
  options.pixel_cost = PixelCost::kBirchfieldTomasiOneSided;
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 58);
}

// The grey levels at a quarter scale added to the x-Sobel costs: one camera and several, direct
// and interpolated (baselines of 2), best half, Birchfield-Tomasi, and 32-bit scores.
TEST(SadMatcherTest, IntensityTermAddsTheQuarterScaleGreyLevelsTheSlowWay) {
  StereoOptions options = matchOptions();
  options.intensity_term = true;
  expectMatchesBruteForce({{1, 0}}, options, Prefilter::kXSobel);
  expectMatchesBruteForce({{-1, 0}, {0, -1}, {1, 1}}, options, Prefilter::kXSobel);
  options.combination = CameraCombination::kBestHalf;
  expectMatchesBruteForce({{-2, 0}, {-1, 0}, {1, 0}, {2, 0}}, options, Prefilter::kXSobel);
  options.combination = CameraCombination::kSum;
  options.pixel_cost = PixelCost::kBirchfieldTomasi;
  expectMatchesBruteForce({{1, 0}, {-2, 0}}, options, Prefilter::kXSobel);
  options.pixel_cost = PixelCost::kBirchfieldTomasiOneSided;
  expectMatchesBruteForce({{-1, 0}, {2, 0}, {0, 1}}, options, Prefilter::kXSobel);
  options.window = 15;  // 225 * (62 + 64) * 2 cameras > 32767
  options.max_disparity = 10;
  expectMatchesBruteForce({{1, 0}, {0, 1}}, options, Prefilter::kXSobel);
}

TEST(SadMatcherTest, IntensityTermWithPathsEqualsTheSlowWay) {
  StereoOptions options = matchOptions();
  options.window = 3;
  options.max_disparity = 12;
  options.intensity_term = true;
  options.aggregation = CostAggregation::kScanline;
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70, Prefilter::kXSobel);
  options.pixel_cost = PixelCost::kBirchfieldTomasiOneSided;
  expectPathsMatchBruteForce({{1, 0}}, options, 12, 70, Prefilter::kXSobel);
  options.aggregation = CostAggregation::kSemiGlobal;
  options.pixel_cost = PixelCost::kBirchfieldTomasi;
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 58, Prefilter::kXSobel);
}

// With partial_candidates the binocular rig's edge band joins the rest of the row in one region:
// its candidates off the image are scored against the replicated border, the paths and the
// left-right check's reverse match run across the whole row, and a best candidate off the image
// leaves the pixel without a disparity.
TEST(SadMatcherTest, PartialCandidatesMatchTheEdgeBandTheSlowWay) {
  StereoOptions options = smallPathOptions(CostAggregation::kScanline);
  options.partial_candidates = true;
  expectPathsMatchBruteForce({{1, 0}}, options, 0, 70);
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 70);
  // Off the image the candidates' sampling intervals are those of the border pixel.
  options.pixel_cost = PixelCost::kBirchfieldTomasiOneSided;
  expectPathsMatchBruteForce({{1, 0}}, options, 0, 70);
  expectPathsMatchBruteForce({{-1, 0}}, options, 0, 70);
  options.pixel_cost = PixelCost::kAbsoluteDifference;
  // Columns 0-3 miss even the nearest candidate; the margin covers the band's farthest reads.
  options.min_disparity = 4;
  options.aggregation = CostAggregation::kSemiGlobal;
  expectPathsMatchBruteForce({{1, 0}}, options, 4, 70);
}

// A textured background at disparity 6 seen by a right camera (band on the left) and by a left
// one (band on the right), 16 candidates: inside the band the background is found wherever its
// candidate is on the image, and nowhere else; without partial_candidates the band is empty.
TEST(SadMatcherTest, PartialCandidatesFindTheSurfaceInTheEdgeBand) {
  constexpr int kDisparity = 6, kMaxDisparity = 15, kRadius = 3;
  SyntheticScene scene(kSize, kDisparity, 29);
  const cv::Mat1f truth = scene.trueDisparity();
  const int w = kSize.width, h = kSize.height;
  for (const double bx : {1.0, -1.0}) {
    const StereoFrame frame = renderFrame(scene, {{bx, 0}});
    const auto band = [&](int from, int to) {  // columns [from, to) counted from the band's edge
      return bx > 0 ? cv::Rect(from, 10, to - from, h - 20) : cv::Rect(w - to, 10, to - from, h - 20);
    };
    StereoOptions options = matchOptions();
    const SadMatch without = SadMatcher(options).match(frame);
    EXPECT_EQ(testing::shareInvalid(without.disparity, rectMask(kSize, band(0, kMaxDisparity))), 1.0) << bx;
    options.partial_candidates = true;
    const SadMatch with = SadMatcher(options).match(frame);
    EXPECT_GE(shareCorrect(with.disparity, truth, rectMask(kSize, band(kDisparity + kRadius, kMaxDisparity))), 0.95)
        << bx;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const float d = with.disparity(y, x);
        if (d == kInvalidDisparity) continue;
        const double sample = x - bx * d;
        ASSERT_TRUE(sample >= 0 && sample <= w - 1) << "(" << x << ", " << y << ") d " << d << " camera " << bx;
      }
    }
  }
}

// A flat band is ambiguous for a window inside it (every candidate that keeps the window in the
// band scores 0, and the first, disparity 0, wins); the scanline carries the textured surface's
// disparity across it from both sides.
TEST(SadMatcherTest, ScanlineCarriesTheDisparityAcrossAFlatBand) {
  constexpr int kShift = 6;
  cv::RNG rng(3);
  cv::Mat1b reference(40, 140);
  rng.fill(reference, cv::RNG::UNIFORM, 0, 256);
  reference.colRange(55, 85).setTo(128);
  cv::Mat1b secondary(40, 140, uchar{0});
  reference.colRange(kShift, 140).copyTo(secondary.colRange(0, 140 - kShift));
  StereoOptions options = matchOptions();
  options.window = 5;
  options.left_right_check = false;
  const StereoFrame frame{reference, {{secondary, {1, 0}}}};
  const SadMatch window_only = SadMatcher(options).match(frame);
  options.aggregation = CostAggregation::kScanline;
  const SadMatch scanline = SadMatcher(options).match(frame);
  int window_correct = 0, scanline_correct = 0;
  for (int y = 5; y < 35; ++y) {
    for (int x = 62; x < 78; ++x) {  // windows inside the band
      window_correct += window_only.disparity(y, x) == kShift;
      scanline_correct += scanline.disparity(y, x) == kShift;
    }
  }
  EXPECT_EQ(window_correct, 0);
  EXPECT_EQ(scanline_correct, 30 * 16);
}

// A flat band across the whole image is ambiguous along its rows (every candidate scores 0 there,
// and the paths along the rows stay flat), so the scanline takes the first disparity; the
// semi-global paths from above carry the textured surface's disparity down into it.
TEST(SadMatcherTest, SemiGlobalCarriesTheDisparityDownIntoAFlatBand) {
  constexpr int kShift = 6;
  cv::RNG rng(5);
  cv::Mat1b scene(40, 140 + kShift);
  rng.fill(scene, cv::RNG::UNIFORM, 0, 256);
  scene.rowRange(15, 26).setTo(128);
  const cv::Mat1b reference = scene.colRange(0, 140).clone(), secondary = scene.colRange(kShift, 140 + kShift).clone();
  StereoOptions options = matchOptions();
  options.window = 5;
  options.left_right_check = false;
  options.aggregation = CostAggregation::kScanline;
  const StereoFrame frame{reference, {{secondary, {1, 0}}}};
  const SadMatch scanline = SadMatcher(options).match(frame);
  options.aggregation = CostAggregation::kSemiGlobal;
  const SadMatch semi_global = SadMatcher(options).match(frame);
  int scanline_correct = 0, semi_global_correct = 0;
  for (int y = 18; y < 23; ++y) {  // windows inside the band, x-Sobel's 3x3 included
    for (int x = 20; x < 120; ++x) {
      scanline_correct += scanline.disparity(y, x) == kShift;
      semi_global_correct += semi_global.disparity(y, x) == kShift;
    }
  }
  EXPECT_EQ(scanline_correct, 0);
  EXPECT_EQ(semi_global_correct, 5 * 100);
}

// Every output of two matches, pixel for pixel (invalid disparities compared as equal).
void expectSameMatch(const SadMatch& a, const SadMatch& b) {
  const auto same = [](const cv::Mat& x, const cv::Mat& y) {
    if (x.empty() || y.empty()) return x.empty() && y.empty();
    cv::Mat x_valid = x.clone(), y_valid = y.clone();
    if (x.depth() == CV_32F) {
      x_valid.setTo(-1, x == kInvalidDisparity);
      y_valid.setTo(-1, y == kInvalidDisparity);
    }
    return cv::norm(x_valid, y_valid, cv::NORM_INF) == 0.0;
  };
  EXPECT_TRUE(same(a.disparity, b.disparity));
  EXPECT_TRUE(same(a.best_score, b.best_score));
  EXPECT_TRUE(same(a.score_sum, b.score_sum));
  EXPECT_TRUE(same(a.second_score, b.second_score));
  EXPECT_TRUE(same(a.reverse_disparity, b.reverse_disparity));
}

// The AVX2 loop compares twice the candidates per instruction and pads the disparities to 32
// instead of 16; it must give what the SSE2 loop gives along every path through the loop.
TEST(SadMatcherTest, Avx2GivesTheSameMatchAsSse2) {
  if (!simdSupported(SimdLevel::kAvx2)) GTEST_SKIP() << "this CPU has no AVX2";
  struct Case {
    const char* name;
    std::vector<SecondaryCamera> cameras;
    void (*configure)(StereoOptions&);
  };
  const std::vector<Case> cases{
      {"binocular, 13 candidates, every test", {{1, 0}},
       [](StereoOptions& o) { o.max_disparity = 12, o.second_best_ratio = 0.9, o.subpixel = true; }},
      {"left camera, 41 candidates, scanline", {{-1, 0}},
       [](StereoOptions& o) { o.max_disparity = 40, o.aggregation = CostAggregation::kScanline; }},
      {"trinocular, 64 candidates", {{-1, 0}, {0, -1}}, [](StereoOptions& o) { o.max_disparity = 63; }},
      {"diagonal cameras, best half", {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}},
       [](StereoOptions& o) { o.combination = CameraCombination::kBestHalf; }},
      {"wide scores, scanline", {{1, 0}, {0, 1}},
       [](StereoOptions& o) { o.window = 15, o.max_disparity = 10, o.aggregation = CostAggregation::kScanline; }},
      {"semi-global, 41 candidates", {{1, 0}},
       [](StereoOptions& o) { o.max_disparity = 40, o.aggregation = CostAggregation::kSemiGlobal; }},
      {"Birchfield-Tomasi, three cameras, best half", {{1, 0}, {-1, 0}, {0, 1}},
       [](StereoOptions& o) { o.pixel_cost = PixelCost::kBirchfieldTomasi, o.combination = CameraCombination::kBestHalf; }},
      {"Birchfield-Tomasi, semi-global, interpolated", {{0.5, 0}},
       [](StereoOptions& o) {
         o.pixel_cost = PixelCost::kBirchfieldTomasi, o.aggregation = CostAggregation::kSemiGlobal, o.max_disparity = 20;
       }},
      {"interpolated half baseline", {{0.5, 0}, {0, 0.5}}, [](StereoOptions& o) { o.max_disparity = 20; }},
      {"minimum disparity, threads", {{1, 0}},
       [](StereoOptions& o) { o.min_disparity = 5, o.max_disparity = 36, o.threads = 3; }},
      {"intensity term, Birchfield-Tomasi, scanline, partial candidates, interpolated", {{0.5, 0}},
       [](StereoOptions& o) {
         o.intensity_term = true, o.pixel_cost = PixelCost::kBirchfieldTomasi,
         o.aggregation = CostAggregation::kScanline, o.partial_candidates = true, o.max_disparity = 40;
       }},
      {"one-sided Birchfield-Tomasi, intensity term, scanline, partial candidates, interpolated and diagonal",
       {{0.5, 0}, {1, 1}},
       [](StereoOptions& o) {
         o.intensity_term = true, o.pixel_cost = PixelCost::kBirchfieldTomasiOneSided,
         o.aggregation = CostAggregation::kScanline, o.partial_candidates = true, o.max_disparity = 40;
       }},
      {"intensity term, trinocular, partial candidates", {{-1, 0}, {0, -1}},
       [](StereoOptions& o) { o.intensity_term = true, o.partial_candidates = true, o.min_disparity = 3; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<cv::Mat1b> images;
    const StereoFrame frame = noiseFrame(c.cameras, cv::Size(97, 61), 23, images);
    StereoOptions options = matchOptions();
    c.configure(options);
    options.simd = SimdLevel::kSse2;
    SadMatcher sse2(options);
    options.simd = SimdLevel::kAvx2;
    SadMatcher avx2(options);
    expectSameMatch(sse2.match(frame), avx2.match(frame));
  }
}

TEST(SadMatcherTest, ThreadsGiveTheSameResult) {
  SyntheticScene scene(kSize, 4.0, 17);
  scene.addPlane(kPlane, 10.0);
  const StereoFrame frame = renderFrame(scene, {{-1, 0}, {0, -1}});
  StereoOptions options = matchOptions();
  const SadMatch single = SadMatcher(options).match(frame);
  options.threads = 3;
  const SadMatch striped = SadMatcher(options).match(frame);
  EXPECT_EQ(cv::norm(single.best_score, striped.best_score, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(single.score_sum, striped.score_sum, cv::NORM_INF), 0.0);
  cv::Mat1f a = single.disparity.clone(), b = striped.disparity.clone();
  a.setTo(-1, a == kInvalidDisparity);
  b.setTo(-1, b == kInvalidDisparity);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace stereonav
