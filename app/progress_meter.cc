#include "progress_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace stereonav {
namespace {

constexpr int kBarWidth = 24;
constexpr std::chrono::milliseconds kRedrawInterval(100);

std::string minutesSeconds(double seconds) {
  const long whole = std::lround(std::max(0.0, seconds));
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", whole / 60, whole % 60);
  return text;
}

}  // namespace

ProgressMeter::ProgressMeter(std::ostream& out, std::string label, std::optional<size_t> total)
    : out_(out), label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressMeter::update(size_t done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(done);
}

void ProgressMeter::finish(size_t done) {
  draw(done);
  out_ << "\n" << std::flush;
}

void ProgressMeter::draw(size_t done) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
  char line[160];
  if (total_ && *total_ > 0) {
    const double fraction = std::min(1.0, static_cast<double>(done) / *total_);
    const int filled = static_cast<int>(fraction * kBarWidth);
    const std::string bar = std::string(filled, '#') + std::string(kBarWidth - filled, '.');
    const std::string eta = rate > 0.0 ? minutesSeconds((*total_ - std::min(done, *total_)) / rate) : "?";
    std::snprintf(line, sizeof line, "\r%s [%s] %zu/%zu %3.0f%%  %.1f frames/s  ETA %s  ",
                  label_.c_str(), bar.c_str(), done, *total_, 100.0 * fraction, rate, eta.c_str());
  } else {
    std::snprintf(line, sizeof line, "\r%s %zu frames  %.1f frames/s  ", label_.c_str(), done, rate);
  }
  out_ << line << std::flush;
}

}  // namespace stereonav
