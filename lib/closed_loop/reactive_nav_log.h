#pragma once

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/nav/reactive/CLogFileRecord.h>

#include <string>

namespace stereonav {

// A navigation log in the format of MRPT's reactive navigators (a .reactivenavlog: a
// gzip-compressed stream of serialized mrpt::nav::CLogFileRecord objects), so that MRPT's
// navlog-viewer replays an exploration: per record the robot's pose (localization and odometry),
// the obstacles it sensed (robot frame), its target (robot frame), the velocity command and the
// measured velocity, and the explorer's state as named values and messages ("Show all debug
// fields"). The explorer plans on the grid rather than with PTGs, so records carry no per-PTG
// information (nPTGs = 0, nSelectedPTG = -1), which navlog-viewer shows as "no PTG selected".
class ReactiveNavLog {
 public:
  void append(const mrpt::nav::CLogFileRecord& record);
  size_t size() const { return records_; }

  // Writes every record appended so far to `path` (atomically). Throws std::runtime_error naming
  // `path` if it cannot be written.
  void save(const std::string& path) const;

 private:
  mrpt::io::CMemoryStream serialized_;
  size_t records_ = 0;
};

}  // namespace stereonav
