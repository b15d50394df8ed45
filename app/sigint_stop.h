#pragma once

namespace stereonav {

// While an instance lives, the first Ctrl-C (SIGINT) only raises a flag, so that a long job can
// finish its current step and save what it has; a second Ctrl-C terminates the process as usual.
// The previous handler is restored on destruction. One instance at a time.
class SigintStopRequest {
 public:
  SigintStopRequest();
  ~SigintStopRequest();

  SigintStopRequest(const SigintStopRequest&) = delete;
  SigintStopRequest& operator=(const SigintStopRequest&) = delete;

  bool requested() const;
};

}  // namespace stereonav
