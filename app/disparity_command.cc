#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "common/image_file.h"
#include "common/ini_section.h"
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
  return readImageFile(path, cv::IMREAD_GRAYSCALE);
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
                "evaluation %s: density %.2f%%  bad-0.5 %.2f%%  bad-1.0 %.2f%%  bad-2.0 %.2f%%  mean abs error %.3f "
                "px  inlier rms %.3f px  (%d known pixels)\n",
                name.c_str(), 100.0 * result.density, 100.0 * result.bad_0_5, 100.0 * result.bad_1,
                100.0 * result.bad_2, result.mean_abs_error, result.inlier_rms_error, result.known_pixels);
  std::cout << line;
}

// What the command line asks for, checked for consistency before any file is read.
struct DisparityRequest {
  std::string config_path, reference_path, out_path;
  std::vector<std::string> cameras;
  std::optional<int> max_disparity, window, border;
  bool subpixel = false, spike_removal = false;
  std::optional<std::string> backend, ground_truth_path, nonoccluded_path, discontinuity_path, colour_path;
  std::optional<double> ground_truth_scale;
};

DisparityRequest parseRequest(CommandLine& command_line) {
  DisparityRequest request;
  request.config_path = command_line.required("config");
  request.reference_path = command_line.required("ref");
  request.cameras = command_line.values("cam");
  request.out_path = command_line.required("out");
  request.max_disparity = command_line.intValue("max-disp", 1, kMaxDisparity);
  request.window = command_line.intValue("window", 3, kMaxWindow);
  request.subpixel = command_line.flag("subpixel");
  request.backend = command_line.value("backend");
  request.ground_truth_path = command_line.value("gt");
  request.ground_truth_scale = command_line.doubleValue("gt-scale", 1e-6, 1e6);
  request.nonoccluded_path = command_line.value("gt-nonocc");
  request.discontinuity_path = command_line.value("gt-disc");
  request.border = command_line.intValue("gt-border", 0, 10000);
  request.spike_removal = command_line.flag("spike-removal");
  request.colour_path = command_line.value("colour");
  command_line.rejectUnknown();

  if (request.cameras.empty()) throw UsageError("--cam is required (at least one secondary view)");
  if (!endsWith(request.out_path, ".pfm") && !endsWith(request.out_path, ".png")) {
    throw UsageError("--out '" + request.out_path + "': must end in .pfm or .png");
  }
  if (request.colour_path && !endsWith(*request.colour_path, ".png")) {
    throw UsageError("--colour '" + *request.colour_path + "': must end in .png");
  }
  if (request.ground_truth_path.has_value() != request.ground_truth_scale.has_value()) {
    throw UsageError("--gt and --gt-scale go together");
  }
  if (!request.ground_truth_path && (request.nonoccluded_path || request.discontinuity_path || request.border)) {
    throw UsageError("--gt-nonocc, --gt-disc and --gt-border need --gt");
  }
  if (request.window && *request.window % 2 == 0) {
    throw UsageError("--window " + std::to_string(*request.window) + ": must be odd");
  }
  return request;
}

// The ini's [stereo] section with the command line's values over it.
StereoOptions loadOptions(const DisparityRequest& request, const mrpt::config::CConfigFileBase& config) {
  StereoOptions options = loadIniSection(config, "stereo", loadStereoOptions, request.config_path);
  if (request.max_disparity) options.max_disparity = *request.max_disparity;
  if (request.window) options.window = *request.window;
  if (request.subpixel) options.subpixel = true;
  if (request.backend) {
    try {
      options.backend = parseStereoBackend(*request.backend, "--backend");
    } catch (const ConfigError& error) {
      throw UsageError(error.what());
    }
  }
  return options;
}

std::string sizeText(const cv::Mat& image) { return std::to_string(image.cols) + "x" + std::to_string(image.rows); }

StereoFrame loadFrame(const DisparityRequest& request) {
  StereoFrame frame;
  frame.reference = readGreyImage(request.reference_path);
  for (const std::string& camera : request.cameras) {
    frame.secondaries.push_back(parseCamera(camera));
    const cv::Mat1b& image = frame.secondaries.back().image;
    if (image.size() != frame.reference.size()) {
      throw std::runtime_error(camera.substr(0, camera.rfind(':', camera.rfind(':') - 1)) + ": image is " +
                               sizeText(image) + ", the reference " + request.reference_path + " is " +
                               sizeText(frame.reference));
    }
  }
  return frame;
}

struct GroundTruth {
  cv::Mat1f disparity;
  cv::Mat1b nonoccluded, discontinuities;
};

GroundTruth loadGroundTruth(const DisparityRequest& request, const StereoFrame& frame) {
  GroundTruth truth;
  truth.disparity = loadMiddleburyGroundTruth(*request.ground_truth_path, *request.ground_truth_scale);
  if (truth.disparity.size() != frame.reference.size()) {
    throw std::runtime_error(*request.ground_truth_path + ": ground truth is " + sizeText(truth.disparity) +
                             ", the reference " + request.reference_path + " is " + sizeText(frame.reference));
  }
  truth.nonoccluded = request.nonoccluded_path ? loadMaskFor(*request.nonoccluded_path, truth.disparity)
                                               : nonOccludedMask(truth.disparity, frame.secondaries.front().camera);
  if (request.discontinuity_path) truth.discontinuities = loadMaskFor(*request.discontinuity_path, truth.disparity);
  return truth;
}

void printEvaluations(const DisparityRequest& request, const cv::Mat1f& disparity, const GroundTruth& truth) {
  const int ignored_border = request.border.value_or(18);
  printEvaluation("all", evaluateDisparity(disparity, truth.disparity, ignored_border));
  printEvaluation(request.nonoccluded_path ? "nonocc" : "nonocc (derived from the ground truth)",
                  evaluateDisparity(disparity, truth.disparity, ignored_border, truth.nonoccluded));
  if (request.discontinuity_path) {
    printEvaluation("disc", evaluateDisparity(disparity, truth.disparity, ignored_border, truth.discontinuities));
  }
}

}  // namespace

int runDisparityCommand(const std::vector<std::string>& arguments) {
  CommandLine command_line(arguments, {"help", "subpixel", "spike-removal"});
  if (command_line.flag("help")) {
    std::cout << kUsage;
    return 0;
  }
  const DisparityRequest request = parseRequest(command_line);
  const mrpt::config::CConfigFileMemory config = readConfigFile(request.config_path);
  const StereoOptions options = loadOptions(request, config);
  std::optional<SpikeFilter> spike_filter;
  if (request.spike_removal) {
    spike_filter.emplace(loadIniSection(config, "spike_removal", loadSpikeRemovalOptions, request.config_path));
  }
  const StereoFrame frame = loadFrame(request);
  if (options.max_disparity >= frame.reference.cols) {
    const std::string what = request.max_disparity ? "--max-disp" : request.config_path + ": [stereo] max_disparity";
    throw UsageError(what + " " + std::to_string(options.max_disparity) + ": must be smaller than the image width " +
                     std::to_string(frame.reference.cols));
  }
  validateStereoOptions(options);
  const std::optional<GroundTruth> truth =
      request.ground_truth_path ? std::optional<GroundTruth>(loadGroundTruth(request, frame)) : std::nullopt;

  cv::Mat1f disparity = computeDisparity(frame, options);
  if (spike_filter) {
    cv::Mat1b rejected;
    spike_filter->apply(disparity, rejected);
  }
  writeDisparityImage(request.out_path, disparity);
  if (request.colour_path) writeDisparityColourPng(*request.colour_path, disparity, options.max_disparity);
  std::cout << "disparity: " << request.out_path << " (" << disparity.cols << "x" << disparity.rows << ", "
            << frame.secondaries.size() << " secondary view" << (frame.secondaries.size() > 1 ? "s" : "")
            << ", backend " << toString(options.backend) << (spike_filter ? ", spike removal" : "") << ")\n";
  if (truth) printEvaluations(request, disparity, *truth);
  return 0;
}

}  // namespace stereonav::app
