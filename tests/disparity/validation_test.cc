#include "disparity/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "disparity/disparity_engine.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

using testing::rectMask;
using testing::shareCorrect;
using testing::shareInvalid;
using testing::SyntheticScene;

const cv::Size kSize(120, 90);
const cv::Rect kPlane(50, 25, 40, 40);

// Matching without any validation; each test switches on the one it is about, with the threshold
// stated there.
StereoOptions unvalidated() {
  StereoOptions options;
  options.max_disparity = 15;
  options.texture_threshold = 0.0;
  options.uniqueness_threshold = 1.0;
  options.left_right_check = false;
  return options;
}

StereoFrame binocular(SyntheticScene& scene) { return {scene.view(0, 0), {{scene.view(1, 0), {1, 0}}}}; }

TEST(TextureMapTest, IsZeroOnAFlatImageAndHighOnTexture) {
  cv::Mat1f flat, textured;
  textureMap(cv::Mat1b(40, 40, uchar{90}), 7, 1.0, flat);
  EXPECT_EQ(cv::norm(flat, cv::NORM_INF), 0.0);
  cv::Mat1b stripes(40, 40);
  for (int x = 0; x < 40; ++x) stripes.col(x).setTo((x / 2) % 2 ? 200 : 50);
  textureMap(stripes, 7, 1.0, textured);
  double lowest = 0.0;
  cv::minMaxLoc(textured, &lowest);
  EXPECT_GT(lowest, 10.0);
}

TEST(TextureTest, RejectsAnUntexturedPatchAndKeepsTexture) {
  SyntheticScene scene(kSize, 5.0, 21);
  const cv::Rect patch(30, 25, 40, 40);
  scene.addFlatPatch(patch);
  scene.setNoise(1.5);  // camera noise: the flat patch's scores are noise, not zero
  const StereoFrame frame = binocular(scene);
  // Inside by the window radius plus the Gaussian's reach, so no window sees the patch's outline.
  const cv::Mat1b patch_inside = rectMask(kSize, cv::Rect(patch.x + 7, patch.y + 7, patch.width - 14, patch.height - 14));
  cv::Mat1b textured = rectMask(kSize, cv::Rect(20, 5, 95, 80));
  textured(cv::Rect(patch.x - 4, patch.y - 4, patch.width + 8, patch.height + 8)).setTo(0);

  StereoOptions options = unvalidated();
  const cv::Mat1f accepted = computeDisparity(frame, options);
  EXPECT_LT(shareInvalid(accepted, patch_inside), 0.05);  // without the test the patch gets (noise) matches

  options.texture_threshold = 1.0;
  const cv::Mat1f validated = computeDisparity(frame, options);
  EXPECT_GE(shareInvalid(validated, patch_inside), 0.99);
  EXPECT_GE(shareCorrect(validated, scene.trueDisparity(), textured), 0.99);
}

// Binocular scene with a near plane: the 6 (= 9 - 3) background columns left of it are hidden
// from the right camera, so they have no true match.
struct OcclusionScene {
  SyntheticScene scene{kSize, 3.0, 23};
  cv::Mat1b occluded = rectMask(kSize, cv::Rect(kPlane.x - 6, kPlane.y, 6, kPlane.height));
  // Visible background and plane away from the plane's outline; right of x = 120 - 15 - 3 - 3 the
  // right camera's pixels would need candidates beyond its image when it is the reference.
  cv::Mat1b visible = rectMask(kSize, cv::Rect(20, 5, 79, 80));
  OcclusionScene() {
    scene.addPlane(kPlane, 9.0);
    visible(cv::Rect(kPlane.x - 10, kPlane.y - 4, 18, kPlane.height + 8)).setTo(0);  // occlusion and left edge
    visible(cv::Rect(kPlane.br().x - 4, kPlane.y - 4, 8, kPlane.height + 8)).setTo(0);
    visible(cv::Rect(kPlane.x - 4, kPlane.y - 4, kPlane.width + 8, 8)).setTo(0);
    visible(cv::Rect(kPlane.x - 4, kPlane.br().y - 4, kPlane.width + 8, 8)).setTo(0);
  }
};

TEST(UniquenessTest, RejectsMostOccludedPixelsAndKeepsVisibleOnes) {
  OcclusionScene setup;
  const StereoFrame frame = binocular(setup.scene);
  StereoOptions options = unvalidated();
  EXPECT_EQ(shareInvalid(computeDisparity(frame, options), setup.occluded), 0.0);
  options.uniqueness_threshold = 0.04;
  const cv::Mat1f validated = computeDisparity(frame, options);
  // Occluded background still half-matches similar texture, so only part of it goes (0.31 here),
  // but far more of it than of the visible pixels.
  EXPECT_GE(shareInvalid(validated, setup.occluded), 0.25);
  EXPECT_LE(shareInvalid(validated, setup.visible), 0.01);
  EXPECT_GE(shareCorrect(validated, setup.scene.trueDisparity(), setup.visible), 0.99);
}

TEST(LeftRightCheckTest, RejectsOccludedPixelsAndKeepsVisibleOnes) {
  OcclusionScene setup;
  const StereoFrame frame = binocular(setup.scene);
  StereoOptions options = unvalidated();
  options.left_right_check = true;
  const cv::Mat1f validated = computeDisparity(frame, options);
  EXPECT_GE(shareInvalid(validated, setup.occluded), 0.8);
  EXPECT_GE(shareCorrect(validated, setup.scene.trueDisparity(), setup.visible), 0.99);
}

TEST(UniquenessTest, ComparesBestScoreWithSumOfScores) {
  SadMatch match;
  match.disparity = cv::Mat1f(1, 3, 5.0f);
  match.best_score.create(1, 3);
  match.score_sum.create(1, 3);
  match.best_score << 10, 10, 0;
  match.score_sum << 100, 40, 0;  // ratios 0.1, 0.25, undefined
  cv::Mat1f disparity = match.disparity.clone();
  rejectAmbiguousMatches(disparity, match, 0.2);
  EXPECT_EQ(disparity(0, 0), 5.0f);
  EXPECT_EQ(disparity(0, 1), kInvalidDisparity);
  EXPECT_EQ(disparity(0, 2), kInvalidDisparity);  // all scores zero: nothing to tell candidates apart
}

TEST(DistinctivenessTest, ComparesBestScoreWithTheRunnerUp) {
  SadMatch match;
  match.disparity = cv::Mat1f(1, 4, 5.0f);
  match.best_score.create(1, 4);
  match.second_score.create(1, 4);
  match.best_score << 80, 95, 0, 10;
  match.second_score << 100, 100, 0, std::numeric_limits<int>::max();  // ratios 0.8, 0.95, undefined, ~0
  cv::Mat1f disparity = match.disparity.clone();
  rejectIndistinctMatches(disparity, match, 0.9);
  EXPECT_EQ(disparity(0, 0), 5.0f);
  EXPECT_EQ(disparity(0, 1), kInvalidDisparity);
  EXPECT_EQ(disparity(0, 2), kInvalidDisparity);
  EXPECT_EQ(disparity(0, 3), 5.0f);  // no candidate beyond the neighbours: nothing competes
}

TEST(LeftRightCheckTest, LooksUpTheMatchedPixelInTheSwappedImage) {
  cv::Mat1f disparity(1, 10, kInvalidDisparity), swapped(1, 10, kInvalidDisparity);
  disparity(0, 5) = 2.0f;  // matches x = 3 in the camera at (1, 0)
  disparity(0, 7) = 2.0f;  // matches x = 5
  disparity(0, 1) = 4.0f;  // matches x = -3: outside
  swapped(0, 3) = 3.0f;    // within 1 of 2
  swapped(0, 5) = 4.5f;    // 2.5 away
  rejectInconsistentMatches(disparity, swapped, {1, 0}, 1.0);
  EXPECT_EQ(disparity(0, 5), 2.0f);
  EXPECT_EQ(disparity(0, 7), kInvalidDisparity);
  EXPECT_EQ(disparity(0, 1), kInvalidDisparity);
}

// Every pixel of rows whose width is no multiple of four (horizontal rigs take four pixels at a
// time), against the definition: kept if valid, its match at x - bx*d rounded half up lies in the
// image, and the swapped disparity there is within the limit. Disparities in quarter pixels and
// the baselines are exact in float, so the rounding is unambiguous.
TEST(LeftRightCheckTest, EveryPixelOfHorizontalRigsAsDefined) {
  cv::RNG random(7);
  for (const double bx : {1.0, -1.0, 0.5, -2.0}) {
    cv::Mat1f disparity(5, 23), swapped(5, 23);
    for (int y = 0; y < disparity.rows; ++y) {
      for (int x = 0; x < disparity.cols; ++x) {
        disparity(y, x) = random.uniform(0, 5) == 0 ? kInvalidDisparity : random.uniform(0, 48) / 4.0f;
        swapped(y, x) = random.uniform(0, 5) == 0 ? kInvalidDisparity : random.uniform(0, 48) / 4.0f;
      }
    }
    cv::Mat1f expected = disparity.clone();
    for (int y = 0; y < disparity.rows; ++y) {
      for (int x = 0; x < disparity.cols; ++x) {
        const float d = disparity(y, x);
        if (d == kInvalidDisparity) continue;
        const int xs = static_cast<int>(std::floor(x - bx * d + 0.5));
        const bool kept = xs >= 0 && xs < disparity.cols && std::abs(swapped(y, xs) - d) <= 1.0f;
        if (!kept) expected(y, x) = kInvalidDisparity;
      }
    }
    rejectInconsistentMatches(disparity, swapped, {bx, 0}, 1.0);
    for (int y = 0; y < disparity.rows; ++y) {
      for (int x = 0; x < disparity.cols; ++x) {
        EXPECT_EQ(disparity(y, x), expected(y, x)) << "bx " << bx << " (" << x << ", " << y << ")";
      }
    }
  }
}

// The tests of a stripe of rows read the other rows (the vertical camera's match lies below)
// but write only their own, which is what lets the engine run stripes in parallel.
TEST(LeftRightCheckTest, TestsOnlyTheRowsAskedFor) {
  cv::Mat1f disparity(10, 10, 6.0f), swapped(10, 10, kInvalidDisparity);
  swapped.rowRange(5, 10).setTo(6.0f);  // rows 2..6 match rows 5..9 in the camera at (0, -0.5)
  rejectInconsistentMatches(disparity, swapped, {0, -0.5}, 0.0, cv::Range(2, 4));
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) EXPECT_EQ(disparity(y, x), 6.0f) << "(" << x << ", " << y << ")";
  }
  rejectInconsistentMatches(disparity, swapped, {0, -0.5}, 0.0, cv::Range(7, 9));  // matches below the image
  EXPECT_EQ(cv::countNonZero(disparity == kInvalidDisparity), 20);
  EXPECT_EQ(cv::countNonZero(disparity.rowRange(7, 9) == kInvalidDisparity), 20);
}

TEST(UniquenessTest, TestsOnlyTheRowsAskedFor) {
  SadMatch match;
  match.disparity = cv::Mat1f(4, 3, 5.0f);
  match.best_score = cv::Mat1i(4, 3, 50);
  match.score_sum = cv::Mat1i(4, 3, 100);  // every ratio 0.5: all rejected at 0.2
  cv::Mat1f disparity = match.disparity.clone();
  rejectAmbiguousMatches(disparity, match, 0.2, cv::Range(1, 3));
  EXPECT_EQ(cv::countNonZero(disparity.rowRange(1, 3) == kInvalidDisparity), 6);
  EXPECT_EQ(cv::countNonZero(disparity == kInvalidDisparity), 6);
}

TEST(LeftRightCheckTest, FollowsVerticalAndFractionalBaselines) {
  cv::Mat1f disparity(10, 10, kInvalidDisparity), swapped(10, 10, kInvalidDisparity);
  disparity(2, 4) = 6.0f;  // camera at (0, -0.5): matched pixel at y = 2 + 3 = 5
  swapped(5, 4) = 6.0f;
  rejectInconsistentMatches(disparity, swapped, {0, -0.5}, 0.0);
  EXPECT_EQ(disparity(2, 4), 6.0f);
}

// A bright, faintly textured near plane (a painted door jamb) before a dim, faintly textured wall
// at disparity 4: windows beside the plane are ruled by its edge and matched at its disparity.
struct FatteningScene {
  static constexpr double kNear = 12, kFar = 4;
  SyntheticScene scene{kSize, kFar};
  FatteningScene() {
    scene.addPlane(cv::Rect(-20, -20, kSize.width + 40, kSize.height + 40), kFar, 60, 100);
    scene.addPlane(kPlane, kNear, 190, 230);
  }
  // Pixels outside the plane that read nearer than midway to it, per row of the plane.
  static double spreadPerRow(const cv::Mat1f& disparity) {
    int spread = 0;
    for (int y = kPlane.y; y < kPlane.y + kPlane.height; ++y) {
      for (int x = 0; x < disparity.cols; ++x) {
        const bool outside = x < kPlane.x || x >= kPlane.x + kPlane.width;
        spread += outside && isValidDisparity(disparity(y, x)) && disparity(y, x) > (kNear + kFar) / 2;
      }
    }
    return static_cast<double>(spread) / kPlane.height;
  }
};

TEST(FattenedEdgeTest, TrimsTheNearSurfaceBackToItsBrightnessStep) {
  FatteningScene setup;
  const StereoFrame frame = binocular(setup.scene);
  StereoOptions options = unvalidated();
  options.left_right_check = true;
  const cv::Mat1f matched = computeDisparity(frame, options);
  // Up to half a window (3 pixels) beside each side of the plane reads its disparity (the
  // left-right check keeps them: the reverse match is fattened alike).
  EXPECT_GE(FatteningScene::spreadPerRow(matched), 2.0);
  options.fattening_min_step = 20;
  const cv::Mat1f trimmed = computeDisparity(frame, options);
  EXPECT_LE(FatteningScene::spreadPerRow(trimmed), 0.25);
  // The plane itself keeps its disparity up to its borders.
  const cv::Mat1b plane = rectMask(kSize, kPlane);
  EXPECT_GE(shareCorrect(trimmed, setup.scene.trueDisparity(), plane), 0.97);
}

TEST(FattenedEdgeTest, LeavesAJumpWithoutABrightnessStepAsItIs) {
  cv::Mat1f disparity(1, 40, 4.0f);
  disparity.colRange(0, 20).setTo(12.0f);
  const cv::Mat1b flat(1, 40, uchar{100});
  cv::Mat1f tested = disparity.clone();
  rejectFattenedEdges(tested, flat, 7, 2, 20);
  EXPECT_EQ(cv::countNonZero(tested != disparity), 0);
  // A step of 30 grey levels two pixels inside the near side: the two pixels beyond it go.
  cv::Mat1b stepped = flat.clone();
  stepped.colRange(0, 18).setTo(130);
  rejectFattenedEdges(tested, stepped, 7, 2, 20);
  for (int x = 0; x < 40; ++x) {
    EXPECT_EQ(isValidDisparity(tested(0, x)), x < 18 || x >= 20) << x;
  }
}

TEST(FattenedEdgeTest, NearSurfaceOnTheRightAndAcrossAGapOfInvalidPixels) {
  cv::Mat1f disparity(1, 40, 4.0f);
  disparity.colRange(7, 40).setTo(12.0f);
  disparity(0, 5) = disparity(0, 6) = kInvalidDisparity;  // occluded, rejected by the left-right check
  cv::Mat1b reference(1, 40, uchar{100});
  reference.colRange(10, 40).setTo(60);  // the plane truly starts at column 10
  rejectFattenedEdges(disparity, reference, 7, 2, 20);
  for (int x = 0; x < 40; ++x) {
    EXPECT_EQ(isValidDisparity(disparity(0, x)), x < 5 || x >= 10) << x;
  }
}

// A near surface narrower than two windows (13 pixels for a window of 7: a pole or a table leg,
// fattened) keeps its fattened width even where a brightness step lies inside it; 14 pixels are
// trimmed.
TEST(FattenedEdgeTest, LeavesThinSurfacesFattened) {
  for (const int near_width : {13, 14}) {
    cv::Mat1f disparity(1, 40, 4.0f);
    disparity.colRange(10, 10 + near_width).setTo(12.0f);
    cv::Mat1b reference(1, 40, uchar{100});
    reference.colRange(12, 8 + near_width).setTo(160);  // the surface is two pixels narrower each side
    rejectFattenedEdges(disparity, reference, 7, 2, 20);
    int near = 0;
    for (int x = 0; x < 40; ++x) near += isValidDisparity(disparity(0, x)) && disparity(0, x) > 8;
    EXPECT_EQ(near, near_width == 13 ? 13 : near_width - 4) << near_width;
  }
}

TEST(FattenedEdgeTest, TestsOnlyTheRowsAskedFor) {
  cv::Mat1f disparity(3, 40, 4.0f);
  disparity.colRange(0, 20).setTo(12.0f);
  cv::Mat1b reference(3, 40, uchar{100});
  reference.colRange(0, 18).setTo(130);
  rejectFattenedEdges(disparity, reference, 7, 2, 20, cv::Range(1, 2));
  for (int y = 0; y < 3; ++y) {
    EXPECT_EQ(isValidDisparity(disparity(y, 18)), y != 1) << y;
    EXPECT_EQ(isValidDisparity(disparity(y, 19)), y != 1) << y;
  }
}

}  // namespace
}  // namespace stereonav
