// Termination signals as a polled flag; see Interruption.h.
#include "tests/support/cluster/Interruption.h"

#include <signal.h>
#include <string.h>

#include <algorithm>
#include <csignal>
#include <string>
#include <thread>

namespace rgnav::testing {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void remember(int signal) { received = signal; }

}  // namespace

void catchInterruptions() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = remember;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
    return true;
  }();
  (void)installed;
}

void throwIfInterrupted() {
  if (const int signal = received; signal != 0)
    throw InterruptedError(std::string("interrupted by ") + strsignal(signal));
}

void sleepUntilOrInterrupted(std::chrono::steady_clock::time_point until) {
  for (auto now = std::chrono::steady_clock::now(); now < until; now = std::chrono::steady_clock::now()) {
    std::this_thread::sleep_until(std::min(until, now + std::chrono::milliseconds(50)));
    throwIfInterrupted();
  }
}

}  // namespace rgnav::testing
