#include "assembly/mumps_handle.hpp"

#include "assembly/error.hpp"

namespace pc {
namespace {

constexpr MUMPS_INT kInitialize = -1;
constexpr MUMPS_INT kTerminate = -2;
// The Fortran handle of MPI_COMM_WORLD, which the sequential library's MPI stub accepts without MPI_Init.
constexpr MUMPS_INT kUseCommWorld = -987654;
// INFO(1) for a numerically singular matrix (INFO(2) then counts the pivots eliminated before).
constexpr MUMPS_INT kNumericallySingular = -10;

}  // namespace

MumpsHandle::MumpsHandle(const char* owner) : owner_(owner) {
  mumps_.sym = 0;  // general unsymmetric matrix: LU
  mumps_.par = 1;  // the host process works too
  mumps_.comm_fortran = kUseCommWorld;
  mumps_.job = kInitialize;
  dmumps_c(&mumps_);
  require(mumps_.info[0] >= 0, owner_, ": MUMPS initialization failed with INFO(1) = ", mumps_.info[0]);
  // Initialization set the defaults; silence error, warning and statistics output (we throw instead).
  icntl(1) = -1;
  icntl(2) = -1;
  icntl(3) = -1;
  icntl(4) = 0;
}

MumpsHandle::~MumpsHandle() {
  mumps_.job = kTerminate;
  dmumps_c(&mumps_);
}

// CSR order is a valid coordinate order, so the values array of the same matrix serves MUMPS as is.
void MumpsHandle::set_pattern(const CsrMatrix& a) {
  rows_.resize(a.nonZeros());
  cols_.resize(a.nonZeros());
  for (int row = 0; row < a.rows(); ++row)
    for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot) {
      rows_[slot] = row + 1;
      cols_[slot] = a.innerIndexPtr()[slot] + 1;
    }
  mumps_.n = static_cast<MUMPS_INT>(a.rows());
  mumps_.nnz = a.nonZeros();
  mumps_.irn = rows_.data();
  mumps_.jcn = cols_.data();
  mumps_.a = nullptr;  // no values: the analysis depends on the pattern only
}

bool MumpsHandle::has_pattern(const CsrMatrix& a) const {
  if (!a.isCompressed() || a.rows() != a.cols() || a.rows() != mumps_.n || a.nonZeros() != long(rows_.size()))
    return false;
  for (int row = 0; row < a.rows(); ++row)
    for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot)
      if (rows_[slot] != row + 1 || cols_[slot] != a.innerIndexPtr()[slot] + 1) return false;
  return true;
}

void MumpsHandle::run(Job job, const char* phase) {
  mumps_.job = job;
  dmumps_c(&mumps_);
  const MUMPS_INT info1 = mumps_.info[0];
  const MUMPS_INT info2 = mumps_.info[1];
  if (info1 == kNumericallySingular)
    fail(owner_, ": the matrix is numerically singular (", phase, " failed with INFO(1) = ", info1, ", INFO(2) = ", info2,
         ")");
  // -13: an allocation inside MUMPS failed (-9 is a work array sized too small, which ICNTL(14) mends).
  if (info1 == -13)
    throw OutOfMemory(message(owner_, ": the ", phase, " ran out of memory (INFO(1) = ", info1, ", INFO(2) = ", info2, ")"));
  require(info1 >= 0, owner_, ": the ", phase, " failed with INFO(1) = ", info1, ", INFO(2) = ", info2,
          " (see the MUMPS manual)");
}

}  // namespace pc
