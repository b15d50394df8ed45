#include "disparity/validation.h"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "disparity/disparity_image.h"
#include "disparity/prefilter.h"

namespace stereonav {

namespace {

// `rows` of an image of `height` rows (Range::all() is every row).
cv::Range rowsOf(const cv::Range& rows, int height) {
  return rows == cv::Range::all() ? cv::Range(0, height) : rows;
}

// Keeps the pixels whose best score is below `ratio` times `reference`'s score.
void keepBestBelow(cv::Mat1f& disparity, const cv::Mat1i& best_score, const cv::Mat1i& reference, double ratio,
                   const cv::Range& rows) {
  CV_Assert(disparity.size() == best_score.size() && disparity.size() == reference.size());
  const float factor = static_cast<float>(ratio);
  const cv::Range tested = rowsOf(rows, disparity.rows);
  for (int y = tested.start; y < tested.end; ++y) {
    float* row = disparity.ptr<float>(y);
    const int* best = best_score.ptr<int>(y);
    const int* other = reference.ptr<int>(y);
    for (int x = 0; x < disparity.cols; ++x) {
      // Branch-free, so the compiler vectorises it.
      row[x] = static_cast<float>(best[x]) < factor * static_cast<float>(other[x]) ? row[x] : kInvalidDisparity;
    }
  }
}

}  // namespace

void textureMap(const cv::Mat1b& reference, int window, double sigma, cv::Mat1f& texture) {
  thread_local cv::Mat1f magnitude;  // scratch, reused from call to call
  laplacianOfGaussian(reference, sigma, magnitude);
  cv::absdiff(magnitude, cv::Scalar::all(0), magnitude);
  // The window's mean as two passes of float sums: cv::boxFilter sums float images in double,
  // which costs twice as much for a difference far below the threshold's resolution.
  const cv::Mat mean_kernel(window, 1, CV_32F, cv::Scalar::all(1.0 / window));
  cv::sepFilter2D(magnitude, texture, CV_32F, mean_kernel, mean_kernel, cv::Point(-1, -1), 0.0,
                  cv::BORDER_REPLICATE);
}

void rejectLowTexture(cv::Mat1f& disparity, const cv::Mat1f& texture, double threshold, const cv::Range& rows) {
  CV_Assert(disparity.size() == texture.size());
  const float minimum = static_cast<float>(threshold);
  const cv::Range tested = rowsOf(rows, disparity.rows);
  for (int y = tested.start; y < tested.end; ++y) {
    float* row = disparity.ptr<float>(y);
    const float* texture_row = texture.ptr<float>(y);
    for (int x = 0; x < disparity.cols; ++x) row[x] = texture_row[x] > minimum ? row[x] : kInvalidDisparity;
  }
}

void rejectAmbiguousMatches(cv::Mat1f& disparity, const SadMatch& match, double threshold, const cv::Range& rows) {
  keepBestBelow(disparity, match.best_score, match.score_sum, threshold, rows);
}

void rejectIndistinctMatches(cv::Mat1f& disparity, const SadMatch& match, double ratio, const cv::Range& rows) {
  keepBestBelow(disparity, match.best_score, match.second_score, ratio, rows);
}

void rejectInconsistentMatches(cv::Mat1f& disparity, const cv::Mat1f& swapped, const SecondaryCamera& first,
                               double max_difference, const cv::Range& rows) {
  CV_Assert(disparity.size() == swapped.size());
  const int width = disparity.cols, height = disparity.rows;
  const cv::Range tested = rowsOf(rows, height);
  const float bx = static_cast<float>(first.bx), by = static_cast<float>(first.by);
  const float limit = static_cast<float>(max_difference);
  // Branch-free: valid and invalid pixels are mixed at random, which a branch would mispredict
  // (and std::lround is a library call). The matched pixel is rounded half up, as lround does
  // for these coordinates; an invalid swapped disparity (+inf) fails the comparison.
  const auto test = [&](float* row, int y, int x) {
    const float d = row[x];
    const bool valid = isValidDisparity(d);
    const float shift = valid ? d : 0.0f;
    const int xs = cvFloor(static_cast<float>(x) - bx * shift + 0.5f);
    const int ys = by == 0.0f ? y : cvFloor(static_cast<float>(y) - by * shift + 0.5f);
    const bool inside = valid && static_cast<unsigned>(xs) < static_cast<unsigned>(width) &&
                        static_cast<unsigned>(ys) < static_cast<unsigned>(height);
    const float seen = swapped(inside ? ys : 0, inside ? xs : 0);
    row[x] = inside && std::abs(seen - d) <= limit ? d : kInvalidDisparity;
  };
  for (int y = tested.start; y < tested.end; ++y) {
    float* row = disparity.ptr<float>(y);
    int x = 0;
    if (by == 0.0f) {
      // A horizontal camera's matches lie on the same row: four pixels at a time, the matched
      // pixels gathered (the test above, lane by lane).
      const float* swapped_row = swapped.ptr<float>(y);
      const cv::v_float32x4 invalid = cv::v_setall_f32(kInvalidDisparity), half = cv::v_setall_f32(0.5f);
      const cv::v_float32x4 baseline = cv::v_setall_f32(bx), limits = cv::v_setall_f32(limit);
      const cv::v_int32x4 columns = cv::v_setall_s32(width);
      cv::v_float32x4 xf(0.0f, 1.0f, 2.0f, 3.0f);
      for (; x + 4 <= width; x += 4, xf += cv::v_setall_f32(4.0f)) {
        const cv::v_float32x4 d = cv::v_load(row + x);
        const cv::v_float32x4 valid = d != invalid;
        const cv::v_int32x4 xs = cv::v_floor(xf - baseline * (d & valid) + half);
        const cv::v_int32x4 inside = cv::v_reinterpret_as_s32(valid) & (xs >= cv::v_setall_s32(0)) & (xs < columns);
        const cv::v_float32x4 seen = cv::v_lut(swapped_row, xs & inside);
        const cv::v_float32x4 keep = cv::v_reinterpret_as_f32(inside) & (cv::v_abs(seen - d) <= limits);
        cv::v_store(row + x, cv::v_select(keep, d, invalid));
      }
    }
    for (; x < width; ++x) test(row, y, x);
  }
}

void rejectFattenedEdges(cv::Mat1f& disparity, const cv::Mat1b& reference, int window, double min_jump,
                         double min_step, const cv::Range& rows) {
  CV_Assert(disparity.size() == reference.size());
  const int width = disparity.cols, height = disparity.rows, half_window = window / 2;
  const cv::Range tested = rowsOf(rows, height);
  thread_local std::vector<float> matched;  // the row as matched, before any pixel is rejected
  matched.resize(width);
  for (int y = tested.start; y < tested.end; ++y) {
    float* row = disparity.ptr<float>(y);
    std::copy(row, row + width, matched.begin());
    const uchar* lines[3] = {reference.ptr<uchar>(std::max(y - 1, 0)), reference.ptr<uchar>(y),
                             reference.ptr<uchar>(std::min(y + 1, height - 1))};
    // The brightness step between columns x and x + 1, read only near jumps.
    const auto step = [&](int x) {
      int sum = 0;
      for (const uchar* line : lines) sum += line[x + 1] - line[x];
      return std::abs(static_cast<float>(sum)) / 3.0f;
    };
    // The strongest step between columns [from, to), or -1 if none reaches min_step.
    const auto strongestStep = [&](int from, int to) {
      int best = -1;
      float strongest = static_cast<float>(min_step);
      for (int x = std::max(from, 0); x < std::min(to, width - 1); ++x) {
        const float here = step(x);
        if (here >= strongest) {
          strongest = here;
          best = x;
        }
      }
      return best;
    };
    const auto rejectNear = [&](int from, int to, float threshold) {  // [from, to]
      for (int x = from; x <= to; ++x) {
        if (isValidDisparity(matched[x]) && matched[x] > threshold) row[x] = kInvalidDisparity;
      }
    };
    // Whether the near surface at `from` runs on for two windows in direction `dir` (disparity
    // continuous from pixel to pixel): a narrower one (a pole, a table leg) is left fattened.
    const int min_width = 2 * window;
    const auto wide = [&](int from, int dir) {
      int run = 1;
      for (int x = from + dir; run < min_width && x >= 0 && x < width; x += dir, ++run) {
        if (!isValidDisparity(matched[x]) || std::abs(matched[x] - matched[x - dir]) >= min_jump) break;
      }
      return run >= min_width;
    };
    int previous = -1;
    for (int x = 0; x < width; ++x) {
      if (!isValidDisparity(matched[x])) continue;
      const int a = previous, b = x;
      previous = x;
      // Between the two lie at most the pixels the far camera cannot see (as many as the jump)
      // and a window's worth the tests rejected.
      if (a < 0 || static_cast<float>(b - a) > static_cast<float>(window) + std::abs(matched[a] - matched[b])) {
        continue;
      }
      const float middle = 0.5f * (matched[a] + matched[b]);
      if (matched[a] - matched[b] >= min_jump) {
        // Near surface on the left: its true right border lies at or before a.
        if (!wide(a, -1)) continue;
        const int edge = strongestStep(a - half_window, b);
        if (edge >= 0 && edge < a) rejectNear(edge + 1, a, middle);
      } else if (matched[b] - matched[a] >= min_jump) {
        // Near surface on the right: its true left border lies at or after b.
        if (!wide(b, 1)) continue;
        const int edge = strongestStep(a, b + half_window);
        if (edge >= b) rejectNear(b, edge, middle);
      }
    }
  }
}

}  // namespace stereonav
