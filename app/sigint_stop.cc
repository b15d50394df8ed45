#include "sigint_stop.h"

#include <csignal>
#include <stdexcept>

namespace stereonav {
namespace {

volatile std::sig_atomic_t stop_requested = 0;
struct sigaction previous_action;

void onSigint(int) { stop_requested = 1; }

}  // namespace

SigintStopRequest::SigintStopRequest() {
  stop_requested = 0;
  struct sigaction action {};
  action.sa_handler = onSigint;
  sigemptyset(&action.sa_mask);
  // The handler is reset to the default after the first signal: a second Ctrl-C kills.
  action.sa_flags = SA_RESETHAND;
  if (sigaction(SIGINT, &action, &previous_action) != 0) {
    throw std::runtime_error("cannot install the SIGINT handler");
  }
}

SigintStopRequest::~SigintStopRequest() { sigaction(SIGINT, &previous_action, nullptr); }

bool SigintStopRequest::requested() const { return stop_requested != 0; }

}  // namespace stereonav
