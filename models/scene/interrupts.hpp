#pragma once
// SIGINT and SIGTERM as requests to stop: the runner installs the handlers, and a running time loop stops
// at the end of its current step, so that its results so far, its summary and the stop reason are written
// and the process exits non-zero instead of dying mid-write.
#include <string>

namespace pc {

// Installs the handlers (once; later calls do nothing).
void install_interrupt_handlers();
// "interrupted by SIGINT" / "interrupted by SIGTERM" once a signal arrived, else null.
const char* interrupt_reason();
// The same, agreed by the processes of a distributed run (collective): a reason on every process once
// one of them was interrupted, else empty.
std::string agreed_interrupt_reason();

}  // namespace pc
