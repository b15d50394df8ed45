#pragma once

namespace stereonav {

// While an instance lives, the first Ctrl-C (SIGINT) or SIGTERM (what service managers and ROS
// send to stop a node) only raises a flag, so that a long job can finish its current step and
// save what it has; a second signal of the same kind terminates the process as usual. The
// previous handlers are restored on destruction. One instance at a time.
class SigintStopRequest {
 public:
  SigintStopRequest();
  ~SigintStopRequest();

  SigintStopRequest(const SigintStopRequest&) = delete;
  SigintStopRequest& operator=(const SigintStopRequest&) = delete;

  bool requested() const;
};

}  // namespace stereonav
