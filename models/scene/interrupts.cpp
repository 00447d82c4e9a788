#include "models/scene/interrupts.hpp"

#include <csignal>

#include "assembly/processes.hpp"

namespace pc {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void on_interrupt(int signal) { received = signal; }

}  // namespace

void install_interrupt_handlers() {
  static const bool installed = [] {
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    return true;
  }();
  (void)installed;
}

const char* interrupt_reason() {
  switch (received) {
    case 0: return nullptr;
    case SIGINT: return "interrupted by SIGINT";
    default: return "interrupted by SIGTERM";
  }
}

std::string agreed_interrupt_reason() {
  const char* reason = interrupt_reason();
  if (!processes::any(reason != nullptr)) return "";
  return reason ? reason : "another process of the run was interrupted";
}

}  // namespace pc
