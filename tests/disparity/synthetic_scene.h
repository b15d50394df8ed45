#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <vector>

#include "disparity/disparity_image.h"

namespace stereonav::testing {

// Fronto-parallel textured planes in front of a textured background, rendered exactly for any
// camera of the rig: the camera at baseline (bx, by) sees at pixel p the nearest plane whose
// reference-image area contains p + (bx, by) * d, with that plane's texture (fixed to the plane,
// smooth enough for bilinear sampling at fractional shifts). Flat patches are untextured grey
// regions of the background. The true disparity of the reference view is known everywhere.
class SyntheticScene {
 public:
  SyntheticScene(cv::Size size, double background_disparity, uint64 seed = 1)
      : size_(size), rng_(seed) {
    layers_.push_back({cv::Rect(-kMargin, -kMargin, size.width + 2 * kMargin, size.height + 2 * kMargin),
                       background_disparity, texture()});
  }

  // `area` is where the plane is in the reference image; nearer planes are added later. Its texture
  // spans grey levels darkest..brightest.
  void addPlane(const cv::Rect& area, double disparity, double darkest = 20, double brightest = 235) {
    layers_.push_back({area, disparity, texture(darkest, brightest)});
  }

  // An untextured patch (grey 128) on the background, in reference-image coordinates.
  void addFlatPatch(const cv::Rect& area) { flat_patches_.push_back(area); }

  // Adds uniform noise of +-amplitude grey levels to every rendered view (a different draw per view).
  void setNoise(double amplitude) { noise_ = amplitude; }

  cv::Mat1b view(double bx, double by) {
    cv::Mat1f image(size_);
    for (int v = 0; v < size_.height; ++v) {
      for (int u = 0; u < size_.width; ++u) image(v, u) = sample(u, v, bx, by);
    }
    if (noise_ > 0) {
      cv::Mat1f noise(size_);
      rng_.fill(noise, cv::RNG::UNIFORM, -noise_, noise_);
      image += noise;
    }
    cv::Mat1b result;
    image.convertTo(result, CV_8U);
    return result;
  }

  cv::Mat1f trueDisparity() const {
    cv::Mat1f disparity(size_);
    for (int y = 0; y < size_.height; ++y) {
      for (int x = 0; x < size_.width; ++x) disparity(y, x) = static_cast<float>(visibleLayer(x, y, 0, 0).disparity);
    }
    return disparity;
  }

 private:
  static constexpr int kMargin = 80;  // background texture beyond the image, for shifted views
  struct Layer {
    cv::Rect area;
    double disparity;
    cv::Mat1f texture;  // covers area, indexed from area.tl()
  };

  cv::Mat1f texture(double darkest = 20, double brightest = 235) {
    cv::Mat1f noise(size_.height + 2 * kMargin, size_.width + 2 * kMargin);
    rng_.fill(noise, cv::RNG::UNIFORM, 0.0, 255.0);
    cv::GaussianBlur(noise, noise, cv::Size(), 1.2);
    cv::normalize(noise, noise, darkest, brightest, cv::NORM_MINMAX);
    return noise;
  }

  const Layer& visibleLayer(double u, double v, double bx, double by) const {
    for (auto layer = layers_.rbegin(); layer != layers_.rend(); ++layer) {
      const double x = u + bx * layer->disparity, y = v + by * layer->disparity;
      if (x >= layer->area.x && x < layer->area.x + layer->area.width && y >= layer->area.y &&
          y < layer->area.y + layer->area.height) {
        return *layer;
      }
    }
    return layers_.front();
  }

  float sample(int u, int v, double bx, double by) const {
    const Layer& layer = visibleLayer(u, v, bx, by);
    const double x = u + bx * layer.disparity, y = v + by * layer.disparity;
    if (&layer == &layers_.front()) {
      for (const cv::Rect& patch : flat_patches_) {
        if (x >= patch.x && x < patch.x + patch.width && y >= patch.y && y < patch.y + patch.height) return 128.0f;
      }
    }
    // Bilinear sample of the plane's texture at its own coordinates.
    const double tx = x - layer.area.x, ty = y - layer.area.y;
    const int ix = std::clamp(static_cast<int>(std::floor(tx)), 0, layer.texture.cols - 2);
    const int iy = std::clamp(static_cast<int>(std::floor(ty)), 0, layer.texture.rows - 2);
    const double fx = tx - ix, fy = ty - iy;
    return static_cast<float>((1 - fy) * ((1 - fx) * layer.texture(iy, ix) + fx * layer.texture(iy, ix + 1)) +
                              fy * ((1 - fx) * layer.texture(iy + 1, ix) + fx * layer.texture(iy + 1, ix + 1)));
  }

  cv::Size size_;
  cv::RNG rng_;
  std::vector<Layer> layers_;
  std::vector<cv::Rect> flat_patches_;
  double noise_ = 0.0;
};

// Share of the pixels of `mask` (non-zero) where `disparity` is valid and within `tolerance` of `truth`.
inline double shareCorrect(const cv::Mat1f& disparity, const cv::Mat1f& truth, const cv::Mat1b& mask,
                           double tolerance = 0.5) {
  int total = 0, correct = 0;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (!mask(y, x)) continue;
      ++total;
      correct += isValidDisparity(disparity(y, x)) && std::abs(disparity(y, x) - truth(y, x)) <= tolerance;
    }
  }
  return total ? static_cast<double>(correct) / total : 0.0;
}

// Share of the pixels of `mask` where `disparity` is invalid.
inline double shareInvalid(const cv::Mat1f& disparity, const cv::Mat1b& mask) {
  int total = 0, invalid = 0;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      if (!mask(y, x)) continue;
      ++total;
      invalid += !isValidDisparity(disparity(y, x));
    }
  }
  return total ? static_cast<double>(invalid) / total : 0.0;
}

inline cv::Mat1b rectMask(cv::Size size, const cv::Rect& area) {
  cv::Mat1b mask = cv::Mat1b::zeros(size);
  mask(area & cv::Rect(cv::Point(), size)).setTo(255);
  return mask;
}

}  // namespace stereonav::testing
