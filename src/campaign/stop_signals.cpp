#include "campaign/stop_signals.hpp"

#include <csignal>
#include <initializer_list>

namespace pound {
namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) {
  g_stop = 1;
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = SA_RESTART;  // MPI start-up and file calls are not interrupted by a stop request
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGTERM, SIGUSR1, SIGINT}) sigaction(sig, &sa, nullptr);
  // A file size limit (ulimit -f) makes writes fail with EFBIG, a stop like a full disk,
  // instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
}

bool stop_requested() {
  return g_stop != 0;
}

}  // namespace pound
