#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace stereonav {

// One run of the built `stereonav` program in a child process, measured as the issue asks
// (time and peak memory), with a watchdog so that a regression into a hang fails the test
// instead of stalling the suite.
struct CommandRun {
  int exit_code = -1;     // -1 if killed by a signal
  int signal = 0;         // the signal that ended it, 0 if it exited
  bool timed_out = false;  // killed by the watchdog
  std::string out;        // stdout
  std::string err;        // stderr
  double cpu_seconds = 0.0;   // user + system
  double wall_seconds = 0.0;
  double peak_memory_mb = 0.0;  // maximum resident set size

  // stderr without its final newline; whether it is one line.
  std::string errorText() const;
  bool oneLineError() const;
};

struct RunOptions {
  double timeout_s = 60.0;
  // Injects a full disk: writes beyond this many bytes per file fail (RLIMIT_FSIZE, with SIGXFSZ
  // ignored, so write() returns EFBIG where a full filesystem returns ENOSPC).
  rlim_t file_size_limit = RLIM_INFINITY;
  // Called every few milliseconds while the child runs (e.g. to signal it).
  std::function<void(pid_t)> while_running;
};

CommandRun runStereonav(const std::vector<std::string>& arguments, const RunOptions& options = {});

}  // namespace stereonav
