#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/datetime.h>

#include <deque>
#include <optional>

namespace stereonav {

// The odometry poses received so far, to give each camera capture the pose of its own instant
// when odometry and images arrive as separate streams (nav_msgs/Odometry beside the image
// topics). Poses between two readings are interpolated linearly (heading along the shorter
// arc); an instant after the newest reading has no pose yet, since a later reading may still come.
class OdometryHistory {
 public:
  // `keep_s`: readings older than this before the newest are forgotten.
  explicit OdometryHistory(double keep_s = 10.0) : keep_s_(keep_s) {}

  // Readings must come in time order; an older or equal one than the newest is ignored.
  void add(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& pose);

  // The pose at `stamp`: exact at a reading, interpolated between two, nothing after the newest;
  // before the oldest kept reading, the oldest (the robot did not report earlier).
  std::optional<mrpt::poses::CPose2D> poseAt(mrpt::system::TTimeStamp stamp) const;

  bool empty() const { return readings_.empty(); }
  // The newest pose, for a capture that must be mapped when no later reading will come.
  std::optional<mrpt::poses::CPose2D> newest() const;

 private:
  struct Reading {
    mrpt::system::TTimeStamp stamp;
    mrpt::poses::CPose2D pose;
  };
  double keep_s_;
  std::deque<Reading> readings_;
};

}  // namespace stereonav
