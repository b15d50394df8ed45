#include "observations/camera_image_pairing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace stereonav {
namespace {

// Beyond this many images waiting for a partner (a camera that stopped), the oldest are dropped.
constexpr size_t kMaxPending = 64;

double seconds(mrpt::system::TTimeStamp t) { return mrpt::Clock::toDouble(t); }

std::string timeText(mrpt::system::TTimeStamp t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", seconds(t));
  return text;
}

}  // namespace

ImagePairingOptions loadImagePairingOptions(IniSection& section) {
  ImagePairingOptions options;
  std::istringstream labels(section.getString("camera_labels", ""));
  for (std::string label; labels >> label;) {
    if (std::find(options.labels.begin(), options.labels.end(), label) != options.labels.end()) {
      throw ConfigError("[" + section.name() + "] camera_labels: '" + label + "' given twice");
    }
    options.labels.push_back(label);
  }
  if (options.labels.size() == 1) {
    throw ConfigError("[" + section.name() +
                      "] camera_labels: at least two cameras (reference first), got one");
  }
  options.max_time_difference_s =
      section.getPositive("pairing_tolerance_s", options.max_time_difference_s);
  return options;
}

CameraImagePairer::CameraImagePairer(ImagePairingOptions options)
    : options_(std::move(options)), pending_(options_.labels.size()) {}

bool CameraImagePairer::add(const mrpt::obs::CObservationImage::Ptr& image) {
  const auto found = std::find(options_.labels.begin(), options_.labels.end(), image->sensorLabel);
  if (found == options_.labels.end()) return false;
  auto& queue = pending_[static_cast<size_t>(found - options_.labels.begin())];
  const auto later = std::upper_bound(
      queue.begin(), queue.end(), image->timestamp,
      [](mrpt::system::TTimeStamp t, const auto& queued) { return t < queued->timestamp; });
  queue.insert(later, image);
  for (size_t label = 1; label < pending_.size(); ++label) {
    while (pending_[label].size() > kMaxPending) dropUnused(label, pending_[label][1]->timestamp);
  }
  while (pending_[0].size() > kMaxPending) {
    decided_.push_back({{}, options_.labels[0] + " image at " +
                                timeText(pending_[0].front()->timestamp) +
                                " s: its partners stopped arriving"});
    pending_[0].pop_front();
  }
  decide(false);
  return true;
}

void CameraImagePairer::finish() {
  decide(true);
  for (size_t label = 1; label < pending_.size(); ++label) {
    if (!pending_[label].empty()) {
      dropUnused(label, pending_[label].back()->timestamp + std::chrono::microseconds(1));
    }
  }
}

std::optional<PairedCapture> CameraImagePairer::next() {
  if (decided_.empty()) return std::nullopt;
  PairedCapture capture = std::move(decided_.front());
  decided_.pop_front();
  return capture;
}

void CameraImagePairer::dropUnused(size_t label, mrpt::system::TTimeStamp before) {
  auto& queue = pending_[label];
  while (!queue.empty() && queue.front()->timestamp < before) {
    decided_.push_back({{}, options_.labels[label] + " image at " +
                                timeText(queue.front()->timestamp) + " s: no " +
                                options_.labels[0] + " image within " +
                                std::to_string(options_.max_time_difference_s) + " s"});
    queue.pop_front();
  }
}

void CameraImagePairer::decide(bool at_end) {
  const double tolerance = options_.max_time_difference_s;
  while (!pending_[0].empty()) {
    const auto reference = pending_[0].front();
    const double t = seconds(reference->timestamp);
    PairedCapture capture{{reference}, ""};
    std::vector<size_t> chosen(pending_.size(), 0);
    bool waiting = false;
    for (size_t label = 1; label < pending_.size(); ++label) {
      const auto& queue = pending_[label];
      double best = tolerance;
      bool found = false;
      for (size_t i = 0; i < queue.size(); ++i) {
        const double difference = std::abs(seconds(queue[i]->timestamp) - t);
        if (difference <= best) best = difference, chosen[label] = i, found = true;
      }
      // Until an image past the window arrives, a closer one may still come; nothing beats an
      // image of the same instant (a head whose cameras share one clock), so a live stream's
      // capture is decided as soon as its last camera arrives.
      const bool passed = !queue.empty() && seconds(queue.back()->timestamp) > t + tolerance;
      const bool exact = found && best == 0.0;
      if (!passed && !exact && !at_end) waiting = true;
      if (found) {
        capture.images.push_back(queue[chosen[label]]);
        continue;
      }
      if (capture.missing.empty()) {
        capture.missing = options_.labels[0] + " image at " + timeText(reference->timestamp) +
                          " s: no " + options_.labels[label] + " image within " +
                          std::to_string(tolerance) + " s";
      }
    }
    if (waiting) return;
    pending_[0].pop_front();
    if (capture.missing.empty()) {
      // Partner images before the chosen ones belong to no reference image.
      for (size_t label = 1; label < pending_.size(); ++label) {
        dropUnused(label, pending_[label][chosen[label]]->timestamp);
        pending_[label].pop_front();
      }
    } else {
      capture.images.clear();
      // The partners this reference did find go with it.
      for (size_t label = 1; label < pending_.size(); ++label) {
        auto& queue = pending_[label];
        queue.erase(std::remove_if(queue.begin(), queue.end(),
                                   [&](const auto& image) {
                                     return std::abs(seconds(image->timestamp) - t) <= tolerance;
                                   }),
                    queue.end());
      }
    }
    // Partner images too old for the next reference image belong to none.
    if (!pending_[0].empty()) {
      const auto limit = pending_[0].front()->timestamp -
                         std::chrono::microseconds(static_cast<int64_t>(tolerance * 1e6));
      for (size_t label = 1; label < pending_.size(); ++label) dropUnused(label, limit);
    }
    decided_.push_back(std::move(capture));
  }
}

}  // namespace stereonav
