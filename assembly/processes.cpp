#include "assembly/processes.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "assembly/error.hpp"

#ifdef PIEZOCONTACT_WITH_MPI
// MPI's C interface only (OpenMPI's header otherwise declares its deprecated C++ bindings).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace pc::processes {

void agree_on_failure(std::exception_ptr failure, const std::string& what) {
  if (count() == 1) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  const int failed = int(max(failure ? double(rank()) : -1.0));
  if (failed < 0) return;
  std::string text;
  if (rank() == failed) try {
      std::rethrow_exception(failure);
    } catch (const std::exception& e) {
      text = e.what();
    } catch (...) {
      text = "an exception that is no std::exception";
    }
  broadcast(text, failed);
  if (rank() == failed) std::rethrow_exception(failure);
  fail(what, " failed on process ", failed, " of the run: ", text);
}

#ifdef PIEZOCONTACT_WITH_MPI
namespace {

void finalize_at_exit() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

// MPI_THREAD_FUNNELED: only the main thread calls MPI (the element loops' OpenMP threads never do).
void start(int* argc, char*** argv) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  std::atexit(finalize_at_exit);
}

MPI_Comm world() {
  start(nullptr, nullptr);
  return MPI_COMM_WORLD;
}

}  // namespace

void initialize(int* argc, char*** argv) { start(argc, argv); }

int rank() {
  int r = 0;
  MPI_Comm_rank(world(), &r);
  return r;
}

int count() {
  int n = 1;
  MPI_Comm_size(world(), &n);
  return n;
}

void sum(std::span<double> values) {
  if (count() > 1) MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, world());
}

void max(std::span<double> values) {
  if (count() > 1) MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_MAX, world());
}

double max(double value) {
  max(std::span<double>(&value, 1));
  return value;
}

bool any(bool value) {
  int flag = value ? 1 : 0;
  if (count() > 1) MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_LOR, world());
  return flag != 0;
}

void broadcast(std::span<double> values, int root) {
  if (count() > 1) MPI_Bcast(values.data(), int(values.size()), MPI_DOUBLE, root, world());
}

void broadcast(std::string& text, int root) {
  if (count() == 1) return;
  int size = int(text.size());
  MPI_Bcast(&size, 1, MPI_INT, root, world());
  text.resize(size_t(size));
  MPI_Bcast(text.data(), size, MPI_CHAR, root, world());
}

bool broadcast(bool value, int root) {
  int flag = value ? 1 : 0;
  if (count() > 1) MPI_Bcast(&flag, 1, MPI_INT, root, world());
  return flag != 0;
}

int fortran_world() { return int(MPI_Comm_c2f(world())); }
int fortran_self() {
  start(nullptr, nullptr);
  return int(MPI_Comm_c2f(MPI_COMM_SELF));
}

void abort(int code) {
  std::fflush(stdout);
  std::fflush(stderr);
  MPI_Abort(world(), code);
  std::exit(code);  // not reached
}

#else  // one process

namespace {
// The Fortran handle of MPI_COMM_WORLD that the sequential MUMPS's MPI stub accepts without MPI_Init.
constexpr int kSequentialMumpsWorld = -987654;
}  // namespace

void initialize(int*, char***) {}
int rank() { return 0; }
int count() { return 1; }
void sum(std::span<double>) {}
void max(std::span<double>) {}
double max(double value) { return value; }
bool any(bool value) { return value; }
void broadcast(std::span<double>, int) {}
void broadcast(std::string&, int) {}
bool broadcast(bool value, int) { return value; }
int fortran_world() { return kSequentialMumpsWorld; }
int fortran_self() { return kSequentialMumpsWorld; }
void abort(int code) {
  std::fflush(stdout);
  std::fflush(stderr);
  std::exit(code);
}

#endif

}  // namespace pc::processes
