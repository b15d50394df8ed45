#include "ros_bridge/odometry_history.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>

namespace stereonav {

void OdometryHistory::add(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& pose) {
  if (!readings_.empty() && stamp <= readings_.back().stamp) return;
  readings_.push_back({stamp, pose});
  while (readings_.size() > 2 &&
         mrpt::system::timeDifference(readings_.front().stamp, stamp) > keep_s_) {
    readings_.pop_front();
  }
}

std::optional<mrpt::poses::CPose2D> OdometryHistory::poseAt(mrpt::system::TTimeStamp stamp) const {
  if (readings_.empty() || stamp > readings_.back().stamp) return std::nullopt;
  if (stamp <= readings_.front().stamp) return readings_.front().pose;
  const auto after = std::lower_bound(
      readings_.begin(), readings_.end(), stamp,
      [](const Reading& reading, mrpt::system::TTimeStamp t) { return reading.stamp < t; });
  if (after->stamp == stamp) return after->pose;
  const Reading& before = *(after - 1);
  const double share = mrpt::system::timeDifference(before.stamp, stamp) /
                       mrpt::system::timeDifference(before.stamp, after->stamp);
  const double turn = mrpt::math::wrapToPi(after->pose.phi() - before.pose.phi());
  return mrpt::poses::CPose2D(before.pose.x() + share * (after->pose.x() - before.pose.x()),
                              before.pose.y() + share * (after->pose.y() - before.pose.y()),
                              mrpt::math::wrapToPi(before.pose.phi() + share * turn));
}

std::optional<mrpt::poses::CPose2D> OdometryHistory::newest() const {
  if (readings_.empty()) return std::nullopt;
  return readings_.back().pose;
}

}  // namespace stereonav
