#include "app/cli/interrupt_guard.hpp"

namespace curvefold::cli {

namespace {

std::atomic<bool> interrupted{false};
std::atomic<int> signalCaught{0};

extern "C" void onInterrupt(int signal) {
  signalCaught = signal;  // both lock-free: safe in a signal handler
  interrupted = true;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  interrupted = false;
  signalCaught = 0;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previousInt_);
  sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
}

const std::atomic<bool>& InterruptGuard::flag() {
  return interrupted;
}

int InterruptGuard::caught() {
  return signalCaught.load();
}

}  // namespace curvefold::cli
