#include <mrpt/config/CConfigFile.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "disparity/disparity_engine.h"
#include "disparity/disparity_evaluation.h"
#include "disparity/disparity_io.h"
#include "disparity/stereo_options.h"
#include "rig/camera_rig.h"
#include "spike_removal/spike_filter.h"

namespace stereonav::app {
namespace {

constexpr const char* kUsage =
    "usage: stereonav disparity --config FILE.ini --ref IMG --cam IMG:BX:BY [--cam ...]\n"
    "                           --out OUT.pfm|OUT.png [--max-disp N] [--window N] [--subpixel]\n"
    "                           [--backend sad|bm|sgbm] [--spike-removal] [--colour OUT.png]\n"
    "                           [--gt GT --gt-scale S [--gt-nonocc MASK] [--gt-disc MASK] [--gt-border N]]\n"
    "Disparity image of the reference view (options from the [stereo] section of the ini;\n"
    "command-line values override it). Each --cam is a secondary view and its baseline: a point\n"
    "at disparity d at (x, y) in the reference is at (x - BX*d, y - BY*d) in it.\n"
    "--spike-removal applies the pipeline's next stage, [spike_removal] of the same ini.\n"
    "--gt scores against Middlebury ground truth (value / S = disparity, 0 unknown) on all known\n"
    "pixels, on the non-occluded ones (--gt-nonocc mask, 255 = evaluated; without it, derived from\n"
    "the truth and the first --cam) and near discontinuities (--gt-disc), ignoring a border of N\n"
    "pixels (default 18).\n";

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

cv::Mat1b readGreyImage(const std::string& path) {
  // Checked first so that OpenCV does not print its own warning before our one-line error.
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open image");
  const cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw std::runtime_error(path + ": cannot read image");
  return image;
}

// "IMG:BX:BY"; the path itself may contain colons, so the baseline is the last two fields.
SecondaryView parseCamera(const std::string& text) {
  const auto malformed = [&] { return UsageError("--cam '" + text + "': expected IMAGE:BX:BY, e.g. right.png:1:0"); };
  const size_t second = text.rfind(':');
  if (second == std::string::npos || second == 0) throw malformed();
  const size_t first = text.rfind(':', second - 1);
  if (first == std::string::npos || first == 0) throw malformed();
  SecondaryView view;
  if (!parseFiniteDouble(text.substr(first + 1, second - first - 1), view.camera.bx) ||
      !parseFiniteDouble(text.substr(second + 1), view.camera.by)) {
    throw malformed();
  }
  if (std::abs(view.camera.bx) > kMaxRelativeBaseline || std::abs(view.camera.by) > kMaxRelativeBaseline) {
    throw UsageError("--cam '" + text + "': BX and BY must be in " +
                     describeRange(-kMaxRelativeBaseline, kMaxRelativeBaseline) + " (units of the unit baseline)");
  }
  if (view.camera.bx == 0.0 && view.camera.by == 0.0) {
    throw UsageError("--cam '" + text + "': baseline (0, 0) is the reference camera itself");
  }
  view.image = readGreyImage(text.substr(0, first));
  return view;
}

// Scores against ground truth, on a mask of the same size (checked here so that the message names
// the file).
cv::Mat1b loadMaskFor(const std::string& path, const cv::Mat1f& ground_truth) {
  const cv::Mat1b mask = loadEvaluationMask(path);
  if (mask.size() != ground_truth.size()) {
    throw std::runtime_error(path + ": mask is " + std::to_string(mask.cols) + "x" + std::to_string(mask.rows) +
                             ", the ground truth is " + std::to_string(ground_truth.cols) + "x" +
                             std::to_string(ground_truth.rows));
  }
  return mask;
}

void printEvaluation(const std::string& name, const DisparityEvaluation& result) {
  char line[240];
  std::snprintf(line, sizeof(line),
                "evaluation %s: density %.2f%%  bad-1.0 %.2f%%  bad-2.0 %.2f%%  mean abs error %.3f px  (%d known "
                "pixels)\n",
                name.c_str(), 100.0 * result.density, 100.0 * result.bad_1, 100.0 * result.bad_2,
                result.mean_abs_error, result.known_pixels);
  std::cout << line;
}

}  // namespace

int runDisparityCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help", "subpixel", "spike-removal"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const std::string config_path = command_line.required("config");
  const std::string reference_path = command_line.required("ref");
  const std::vector<std::string> cameras = command_line.values("cam");
  const std::string out_path = command_line.required("out");
  const auto max_disparity = command_line.intValue("max-disp", 1, kMaxDisparity);
  const auto window = command_line.intValue("window", 3, kMaxWindow);
  const bool subpixel = command_line.flag("subpixel");
  const auto backend = command_line.value("backend");
  const auto ground_truth_path = command_line.value("gt");
  const auto ground_truth_scale = command_line.doubleValue("gt-scale", 1e-6, 1e6);
  const auto nonoccluded_path = command_line.value("gt-nonocc");
  const auto discontinuity_path = command_line.value("gt-disc");
  const auto border = command_line.intValue("gt-border", 0, 10000);
  const bool spike_removal = command_line.flag("spike-removal");
  const auto colour_path = command_line.value("colour");
  command_line.rejectUnknown();

  if (cameras.empty()) throw UsageError("--cam is required (at least one secondary view)");
  if (!endsWith(out_path, ".pfm") && !endsWith(out_path, ".png")) {
    throw UsageError("--out '" + out_path + "': must end in .pfm or .png");
  }
  if (colour_path && !endsWith(*colour_path, ".png")) {
    throw UsageError("--colour '" + *colour_path + "': must end in .png");
  }
  if (ground_truth_path.has_value() != ground_truth_scale.has_value()) {
    throw UsageError("--gt and --gt-scale go together");
  }
  if (!ground_truth_path && (nonoccluded_path || discontinuity_path || border)) {
    throw UsageError("--gt-nonocc, --gt-disc and --gt-border need --gt");
  }
  if (window && *window % 2 == 0) throw UsageError("--window " + std::to_string(*window) + ": must be odd");

  if (!std::ifstream(config_path)) throw std::runtime_error(config_path + ": cannot read config file");
  const mrpt::config::CConfigFile config(config_path);
  StereoOptions options = loadIniSection(config, "stereo", loadStereoOptions, config_path);
  std::optional<SpikeFilter> spike_filter;
  if (spike_removal) spike_filter.emplace(loadIniSection(config, "spike_removal", loadSpikeRemovalOptions, config_path));
  if (max_disparity) options.max_disparity = *max_disparity;
  if (window) options.window = *window;
  if (subpixel) options.subpixel = true;
  if (backend) {
    try {
      options.backend = parseStereoBackend(*backend, "--backend");
    } catch (const ConfigError& error) {
      throw UsageError(error.what());
    }
  }

  StereoFrame frame;
  frame.reference = readGreyImage(reference_path);
  for (const std::string& camera : cameras) {
    frame.secondaries.push_back(parseCamera(camera));
    const cv::Mat1b& image = frame.secondaries.back().image;
    if (image.size() != frame.reference.size()) {
      throw std::runtime_error(camera.substr(0, camera.rfind(':', camera.rfind(':') - 1)) + ": image is " +
                               std::to_string(image.cols) + "x" + std::to_string(image.rows) + ", the reference " +
                               reference_path + " is " + std::to_string(frame.reference.cols) + "x" +
                               std::to_string(frame.reference.rows));
    }
  }
  if (options.max_disparity >= frame.reference.cols) {
    const std::string what = max_disparity ? "--max-disp" : config_path + ": [stereo] max_disparity";
    throw UsageError(what + " " + std::to_string(options.max_disparity) + ": must be smaller than the image width " +
                     std::to_string(frame.reference.cols));
  }
  validateStereoOptions(options);
  cv::Mat1f ground_truth;
  cv::Mat1b nonoccluded, discontinuities;
  if (ground_truth_path) {
    ground_truth = loadMiddleburyGroundTruth(*ground_truth_path, *ground_truth_scale);
    if (ground_truth.size() != frame.reference.size()) {
      throw std::runtime_error(*ground_truth_path + ": ground truth is " + std::to_string(ground_truth.cols) + "x" +
                               std::to_string(ground_truth.rows) + ", the reference " + reference_path + " is " +
                               std::to_string(frame.reference.cols) + "x" + std::to_string(frame.reference.rows));
    }
    nonoccluded = nonoccluded_path ? loadMaskFor(*nonoccluded_path, ground_truth)
                                   : nonOccludedMask(ground_truth, frame.secondaries.front().camera);
    if (discontinuity_path) discontinuities = loadMaskFor(*discontinuity_path, ground_truth);
  }

  cv::Mat1f disparity = computeDisparity(frame, options);
  if (spike_filter) {
    cv::Mat1b rejected;
    spike_filter->apply(disparity, rejected);
  }
  writeDisparityImage(out_path, disparity);
  if (colour_path) writeDisparityColourPng(*colour_path, disparity, options.max_disparity);
  std::cout << "disparity: " << out_path << " (" << disparity.cols << "x" << disparity.rows << ", "
            << frame.secondaries.size() << " secondary view" << (frame.secondaries.size() > 1 ? "s" : "")
            << ", backend " << toString(options.backend) << (spike_filter ? ", spike removal" : "") << ")\n";
  if (ground_truth_path) {
    const int ignored_border = border.value_or(18);
    printEvaluation("all", evaluateDisparity(disparity, ground_truth, ignored_border));
    printEvaluation(nonoccluded_path ? "nonocc" : "nonocc (derived from the ground truth)",
                    evaluateDisparity(disparity, ground_truth, ignored_border, nonoccluded));
    if (discontinuity_path) {
      printEvaluation("disc", evaluateDisparity(disparity, ground_truth, ignored_border, discontinuities));
    }
  }
  return 0;
}

}  // namespace stereonav::app
