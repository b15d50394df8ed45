#include "sigint_stop.h"

#include <csignal>
#include <stdexcept>

namespace stereonav {
namespace {

volatile std::sig_atomic_t stop_requested = 0;
struct sigaction previous_sigint;
struct sigaction previous_sigterm;

void onStopSignal(int) { stop_requested = 1; }

}  // namespace

SigintStopRequest::SigintStopRequest() {
  stop_requested = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  // The handler is reset to the default after the first signal: a second one kills.
  action.sa_flags = SA_RESETHAND;
  if (sigaction(SIGINT, &action, &previous_sigint) != 0) {
    throw std::runtime_error("cannot install the SIGINT handler");
  }
  if (sigaction(SIGTERM, &action, &previous_sigterm) != 0) {
    sigaction(SIGINT, &previous_sigint, nullptr);
    throw std::runtime_error("cannot install the SIGTERM handler");
  }
}

SigintStopRequest::~SigintStopRequest() {
  sigaction(SIGINT, &previous_sigint, nullptr);
  sigaction(SIGTERM, &previous_sigterm, nullptr);
}

bool SigintStopRequest::requested() const { return stop_requested != 0; }

}  // namespace stereonav
