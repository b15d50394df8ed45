#include "mapping/debug_panel.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/atomic_file.h"
#include "sensor_model/stereo_sensor_model.h"

namespace stereonav {
namespace {

constexpr int kLabelHeight = 20;
constexpr int kStripHeight = 28;
constexpr int kPlotHeight = 140;
constexpr int kGap = 4;
const cv::Scalar kBackground(40, 40, 40);
const cv::Scalar kLabelColour(255, 255, 255);
const cv::Vec3b kInvalidColour(255, 255, 255);
const cv::Vec3b kRejectedColour(255, 0, 255);  // magenta (BGR)

// The update step that takes an unknown cell all the way to clear or occupied in one reading,
// so the top-down tile shows this frame's regions, not evidence strength.
GridUpdateOptions singleReadingUpdate() {
  GridUpdateOptions update;
  update.update_step = 127;
  update.accuracy_preservation = false;
  return update;
}

void putLabel(cv::Mat3b& panel, const std::string& text, cv::Point top_left) {
  cv::putText(panel, text, top_left + cv::Point(2, kLabelHeight - 6), cv::FONT_HERSHEY_SIMPLEX,
              0.42, kLabelColour, 1, cv::LINE_AA);
}

void paste(cv::Mat3b& panel, const cv::Mat3b& tile, cv::Point top_left) {
  tile.copyTo(panel(cv::Rect(top_left, tile.size())));
}

}  // namespace

DebugPanelRenderer::DebugPanelRenderer(const MappingOptions& options, const CameraRig& rig)
    : rig_(rig),
      stereo_(options.stereo),
      range_m_(options.mapper.panel_range_m),
      image_scale_(std::max(1, static_cast<int>(std::lround(320.0 / rig.reference.width)))),
      regions_(GridLimits{}, singleReadingUpdate().scale),
      inserter_(options.grid.stereo.sensor_model, singleReadingUpdate(), 0.0) {
  const double reach = options.grid.stereo.sensor_model.max_range_m + 0.5;
  view_limits_.min_x = -reach;
  view_limits_.max_x = reach;
  view_limits_.min_y = -reach;
  view_limits_.max_y = reach;
  view_limits_.resolution = range_m_ / 250.0;
  view_limits_.growth_margin_m = 0.0;
  cv::Mat1b levels(1, 256);
  for (int i = 0; i < 256; ++i) levels(0, i) = static_cast<uint8_t>(i);
  cv::applyColorMap(levels, colour_table_, cv::COLORMAP_TURBO);
}

cv::Vec3b DebugPanelRenderer::disparityColour(float disparity) const {
  if (!isValidDisparity(disparity)) return kInvalidColour;
  const double span = std::max(1, stereo_.max_disparity - stereo_.min_disparity);
  const double level = 255.0 * (disparity - stereo_.min_disparity) / span;
  return colour_table_(0, std::clamp(static_cast<int>(std::lround(level)), 0, 255));
}

cv::Mat3b DebugPanelRenderer::disparityTile(const DisparityScanner& scanner) const {
  const cv::Mat1f& disparity = scanner.disparity();
  const cv::Mat1b& rejected = scanner.rejected();
  cv::Mat3b picture(disparity.size());
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      picture(y, x) = rejected(y, x) != 0 ? kRejectedColour : disparityColour(disparity(y, x));
    }
  }
  cv::Mat3b tile;
  cv::resize(picture, tile, cv::Size(), image_scale_, image_scale_, cv::INTER_NEAREST);
  return tile;
}

cv::Mat3b DebugPanelRenderer::columnStripTile(const DisparityScan& scan) const {
  cv::Mat3b row(1, scan.columns());
  for (int column = 0; column < scan.columns(); ++column) {
    row(0, column) = disparityColour(scan.column_disparity[column]);
  }
  cv::Mat3b tile;
  cv::resize(row, tile, cv::Size(scan.columns() * image_scale_, kStripHeight), 0, 0,
             cv::INTER_NEAREST);
  // Blind columns (ProjectionOptions::near_floor_m): the strip's lower third black.
  const int blind_top = kStripHeight * 2 / 3;
  for (int column = 0; column < scan.columns(); ++column) {
    if (scan.blind(column)) {
      tile(cv::Rect(column * image_scale_, blind_top, image_scale_, kStripHeight - blind_top)).setTo(cv::Vec3b(0, 0, 0));
    }
  }
  return tile;
}

cv::Mat3b DebugPanelRenderer::depthPlotTile(const DisparityScan& scan) const {
  const int width = scan.columns() * image_scale_;
  cv::Mat3b tile(kPlotHeight, width, cv::Vec3b(255, 255, 255));
  const int top = 14, bottom = kPlotHeight - 4;
  const auto rowForDepth = [&](double depth) {
    return static_cast<int>(std::lround(bottom - (bottom - top) * std::min(depth, range_m_) / range_m_));
  };
  for (int metre = 1; metre <= static_cast<int>(range_m_); ++metre) {
    const int y = rowForDepth(metre);
    cv::line(tile, {0, y}, {width - 1, y}, cv::Scalar(220, 220, 220), 1);
    cv::putText(tile, std::to_string(metre) + " m", {2, y - 2}, cv::FONT_HERSHEY_SIMPLEX, 0.35,
                cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
  }
  const std::vector<float> depths = columnDepths(scan, rig_);
  for (int column = 0; column < scan.columns(); ++column) {
    if (!scan.valid(column)) continue;
    const int x = column * image_scale_ + image_scale_ / 2;
    const int y = rowForDepth(depths[column]);
    const cv::Scalar colour = depths[column] > range_m_ ? cv::Scalar(0, 0, 220) : cv::Scalar(0, 0, 0);
    cv::rectangle(tile, cv::Rect(x - image_scale_ / 2, y - 1, std::max(1, image_scale_), 3), colour,
                  cv::FILLED);
  }
  return tile;
}

cv::Mat3b DebugPanelRenderer::topDownTile(const DisparityScan& scan, int size) {
  const DisparityScanCamera camera = DisparityScanCamera::fromRig(rig_);
  // The robot pose that puts the camera at the origin looking along +x.
  const mrpt::poses::CPose2D robot_pose =
      mrpt::poses::CPose2D() - cameraFloorPose(camera.pose_on_robot);
  regions_.reset(view_limits_);
  inserter_.insert(scan, camera, robot_pose, regions_);

  // Forward (x) is up the tile, left (y) is left; the camera sits a little above the bottom.
  const double behind = 0.08 * range_m_;
  const double metres_per_pixel = (range_m_ + behind) / size;
  const double half_width = 0.5 * size * metres_per_pixel;
  cv::Mat3b tile(size, size);
  for (int v = 0; v < size; ++v) {
    const double x = range_m_ - (v + 0.5) * metres_per_pixel;
    for (int u = 0; u < size; ++u) {
      const double y = half_width - (u + 0.5) * metres_per_pixel;
      int col, row;
      const uint8_t g = regions_.cellAt(x, y, col, row) ? regions_.occupancy(col, row)
                                                         : regions_.scale().unknown();
      const auto level = static_cast<uint8_t>(255 - g);
      tile(v, u) = cv::Vec3b(level, level, level);
    }
  }
  const auto pixel = [&](double x, double y) {
    return cv::Point(static_cast<int>(std::lround((half_width - y) / metres_per_pixel)),
                     static_cast<int>(std::lround((range_m_ - x) / metres_per_pixel)));
  };
  for (int metre = 1; metre <= static_cast<int>(range_m_); ++metre) {
    cv::circle(tile, pixel(0, 0), static_cast<int>(std::lround(metre / metres_per_pixel)),
               cv::Scalar(200, 160, 80), 1, cv::LINE_AA);
    cv::putText(tile, std::to_string(metre) + " m", pixel(metre, 0) + cv::Point(3, -3),
                cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(200, 160, 80), 1, cv::LINE_AA);
  }
  const double edge = rig_.reference.width - 0.5;
  for (const double column_edge : {-0.5, edge}) {
    const double lateral = (rig_.reference.cx - column_edge) / rig_.reference.focal_px;
    cv::line(tile, pixel(0, 0), pixel(range_m_, range_m_ * lateral), cv::Scalar(0, 160, 255), 1,
             cv::LINE_AA);
  }
  cv::circle(tile, pixel(0, 0), 4, cv::Scalar(0, 0, 255), cv::FILLED);
  return tile;
}

cv::Mat3b DebugPanelRenderer::render(const DisparityScanner& scanner, size_t frame_index,
                                     const mrpt::poses::CPose2D& robot_pose) {
  const DisparityScan& scan = scanner.lastScan();
  cv::Mat3b reference;
  cv::cvtColor(scanner.referenceGrey(), reference, cv::COLOR_GRAY2BGR);
  cv::resize(reference, reference, cv::Size(), image_scale_, image_scale_, cv::INTER_NEAREST);
  const int image_width = reference.cols, image_height = reference.rows;

  const int column_height = kLabelHeight + image_height + kLabelHeight + kStripHeight +
                            kLabelHeight + kPlotHeight;
  const int top_down_size = column_height - kLabelHeight;
  const cv::Point a(kGap, kGap), b(a.x + image_width + kGap, kGap),
      e(b.x + image_width + kGap, kGap);
  const cv::Point c(b.x, b.y + kLabelHeight + image_height), d(b.x, c.y + kLabelHeight + kStripHeight);
  cv::Mat3b panel(column_height + 2 * kGap, e.x + top_down_size + kGap);
  panel.setTo(kBackground);

  putLabel(panel, "(a) reference image", a);
  paste(panel, reference, a + cv::Point(0, kLabelHeight));
  putLabel(panel, "(b) disparity; white invalid, magenta spikes", b);
  paste(panel, disparityTile(scanner), b + cv::Point(0, kLabelHeight));
  putLabel(panel, "(c) column max disparity; black below: blind", c);
  paste(panel, columnStripTile(scan), c + cv::Point(0, kLabelHeight));
  char depth_label[64];
  std::snprintf(depth_label, sizeof depth_label, "(d) depth per column (red: beyond %.0f m)", range_m_);
  putLabel(panel, depth_label, d);
  paste(panel, depthPlotTile(scan), d + cv::Point(0, kLabelHeight));
  putLabel(panel, "(e) this frame: OCC black, CLEAR white", e);
  paste(panel, topDownTile(scan, top_down_size), e + cv::Point(0, kLabelHeight));

  // Caption and colour scale under the reference image.
  const auto total = static_cast<double>(scanner.disparity().total());
  char caption[160];
  std::snprintf(caption, sizeof caption, "frame %zu  pose (%.2f, %.2f, %.0f deg)", frame_index,
                robot_pose.x(), robot_pose.y(), robot_pose.phi() * 180.0 / M_PI);
  putLabel(panel, caption, c - cv::Point(image_width + kGap, 0));
  std::snprintf(caption, sizeof caption, "matched %.0f%%  kept %.0f%%  columns %d/%d",
                100.0 * scanner.matchedPixels() / total, 100.0 * scanner.keptPixels() / total,
                static_cast<int>(std::count_if(scan.column_disparity.begin(),
                                               scan.column_disparity.end(), isValidDisparity)),
                scan.columns());
  putLabel(panel, caption, c - cv::Point(image_width + kGap, -kLabelHeight));
  if (!scan.column_blind.empty()) {
    std::snprintf(caption, sizeof caption, "blind columns %d",
                  static_cast<int>(std::count(scan.column_blind.begin(), scan.column_blind.end(), 1)));
    putLabel(panel, caption, c - cv::Point(image_width + kGap, -2 * kLabelHeight));
  }
  const cv::Point scale_origin = d - cv::Point(image_width + kGap, -2 * kLabelHeight);
  for (int x = 0; x < image_width; ++x) {
    const float disparity = static_cast<float>(
        stereo_.min_disparity + (stereo_.max_disparity - stereo_.min_disparity) * x / (image_width - 1.0));
    cv::line(panel, scale_origin + cv::Point(x, 0), scale_origin + cv::Point(x, 14),
             cv::Scalar(disparityColour(disparity)));
  }
  std::snprintf(caption, sizeof caption, "d = %d (far)", stereo_.min_disparity);
  putLabel(panel, caption, scale_origin + cv::Point(0, 12));
  std::snprintf(caption, sizeof caption, "%d (near)", stereo_.max_disparity);
  putLabel(panel, caption, scale_origin + cv::Point(image_width - 70, 12));
  return panel;
}

void saveDebugPanel(const cv::Mat3b& panel, const std::string& directory, size_t frame_index) {
  char name[32];
  std::snprintf(name, sizeof name, "panel_%06zu.png", frame_index);
  const std::string path = directory + "/" + name;
  // Naming a level makes OpenCV deflate instead of its default run-length strategy, which leaves
  // the noisy camera tiles nearly uncompressed: panels come out half the size.
  writeImageAtomically(path, panel, {cv::IMWRITE_PNG_COMPRESSION, 3});
}

}  // namespace stereonav
