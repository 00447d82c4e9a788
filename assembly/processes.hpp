#pragma once
// The processes a run spans: MPI's world in the MPI build (PIEZOCONTACT_MUMPS_MPI), one process otherwise,
// where every function below is trivial. A model is replicated on every process (mesh, fields, Newton's
// decisions); each process runs the element loops of the cells it owns (models/model.hpp), the sums
// below complete the residual, and MUMPS factorises the distributed matrix. Every function here is
// collective: all processes call it, in the same order.
//
// MPI is started by the first call that needs it (and finished at exit), so a driver works under
// `mpirun` as it is; a driver that starts MPI itself (MPI_Init) is used as it is too.
#include <exception>
#include <span>
#include <string>

namespace pc::processes {

// Starts MPI with the program's arguments (optional: the first collective call starts it without).
void initialize(int* argc, char*** argv);
int rank();
int count();
inline bool distributed() { return count() > 1; }
inline bool is_writer() { return rank() == 0; }  // the process that writes files and prints

// Over all processes: element-wise sums and maxima (in place), the largest value, logical or.
void sum(std::span<double> values);
void max(std::span<double> values);
double max(double value);
bool any(bool value);
// Rank `root`'s values, on every process.
void broadcast(std::span<double> values, int root = 0);
void broadcast(std::string& text, int root = 0);
// Rank `root`'s decision, on every process.
bool broadcast(bool value, int root = 0);

// Collective: whether any process failed (`failure` is this process's, null if none). If one did, every
// process throws: the first failing process its own exception, the others a pc::Error naming `what`,
// that process and its message. On one process, rethrows `failure` if there is one. So that an error met
// by one process (its elements, its files) never leaves the others waiting in the next collective call.
void agree_on_failure(std::exception_ptr failure, const std::string& what);
// Runs `action` and agrees on its failure.
template <class Action> void run_agreed(const std::string& what, Action&& action) {
  std::exception_ptr failure;
  try {
    action();
  } catch (...) {
    failure = std::current_exception();
  }
  agree_on_failure(failure, what);
}

// The Fortran handles of the world's and of this process's communicator, as MUMPS takes them.
int fortran_world();
int fortran_self();

// Ends every process of the run (MPI_Abort) with `code`, after this one printed why: an error on one
// process must not leave the others waiting in a collective call.
[[noreturn]] void abort(int code);

}  // namespace pc::processes
