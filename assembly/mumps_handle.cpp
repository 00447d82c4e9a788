#include "assembly/mumps_handle.hpp"

#include <cstdint>
#include <cstdlib>
#include <mutex>

#include "assembly/error.hpp"
#include "assembly/heap_trim.hpp"
#include "assembly/processes.hpp"

namespace pc {
namespace {

constexpr MUMPS_INT kInitialize = -1;
constexpr MUMPS_INT kTerminate = -2;
constexpr MUMPS_INT kDistributedAssembledInput = 3;  // ICNTL(18)
// INFO(1) for a numerically singular matrix (INFO(2) then counts the pivots eliminated before).
constexpr MUMPS_INT kNumericallySingular = -10;

// MUMPS orders larger matrices with SCOTCH, and SCOTCH 7 coarsens its graphs on as many threads as there
// are cores. Its threaded orderings differ from one process to the next (so did a run's last digits: 3e-12
// in a displacement at 240 x 80, the factors' entries 5.73-5.82 M for one matrix), and under a memory limit
// a failed allocation in one of its threads crashed the process (a segfault in SCOTCHgraphMatch, where
// MUMPS would otherwise report -13). One thread makes both reproducible and safe, for an ordering done
// once per pattern. A value the user set is kept.
void order_on_one_scotch_thread() {
  static std::once_flag once;
  std::call_once(once, [] { setenv("SCOTCH_PTHREAD_NUMBER", "1", /*overwrite=*/0); });
}

// One entry's coordinates mixed into a pattern's fingerprint (a 64-bit multiply-xorshift: a change of any
// index changes the fingerprint but for chance, about 2^-64).
std::uint64_t mix_entry(std::uint64_t hash, int row, int col) {
  hash ^= (std::uint64_t(std::uint32_t(row)) << 32) | std::uint32_t(col);
  hash *= 0x9E3779B97F4A7C15ull;
  return hash ^ (hash >> 29);
}

// Calls visit(row, col) for each coordinate MUMPS is given for `a` (all, or the lower triangle), in CSR
// order, and returns their fingerprint.
template <class Visit> std::uint64_t visit_coordinates(const CsrMatrix& a, bool lower, Visit&& visit) {
  std::uint64_t hash = mix_entry(0, int(a.rows()), int(a.cols()));
  for (int row = 0; row < a.rows(); ++row)
    for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot) {
      const int col = a.innerIndexPtr()[slot];
      if (lower && col > row) continue;
      hash = mix_entry(hash, row, col);
      visit(row, col);
    }
  return hash;
}

// The fingerprint of the coordinates MUMPS is given for `a`, and their count.
std::uint64_t pattern_fingerprint(const CsrMatrix& a, bool lower, std::size_t& entries) {
  entries = 0;
  return visit_coordinates(a, lower, [&](int, int) { ++entries; });
}

}  // namespace

MumpsHandle::MumpsHandle(const char* owner, Scope scope) : owner_(owner), scope_(scope) {
  order_on_one_scotch_thread();
  start(General);
}

MumpsHandle::~MumpsHandle() { stop(); }

void MumpsHandle::start(Symmetry symmetry) {
  mumps_ = DMUMPS_STRUC_C{};
  mumps_.sym = symmetry;
  mumps_.par = 1;  // the host process works too
  mumps_.comm_fortran = distributed() ? processes::fortran_world() : processes::fortran_self();
  mumps_.job = kInitialize;
  dmumps_c(&mumps_);
  require(mumps_.info[0] >= 0, owner_, ": MUMPS initialization failed with INFO(1) = ", mumps_.info[0]);
  // Initialization set the defaults; silence error, warning and statistics output (we throw instead).
  icntl(1) = -1;
  icntl(2) = -1;
  icntl(3) = -1;
  icntl(4) = 0;
  if (distributed()) icntl(18) = kDistributedAssembledInput;
}

void MumpsHandle::stop() {
  mumps_.job = kTerminate;
  dmumps_c(&mumps_);
}

// CSR order is a valid coordinate order, so the values array of the same matrix serves MUMPS as is in
// General mode.
std::uint64_t MumpsHandle::fill_coordinates(const CsrMatrix& a, std::size_t expected) {
  std::vector<MUMPS_INT>().swap(rows_);
  std::vector<MUMPS_INT>().swap(cols_);
  rows_.reserve(expected);
  cols_.reserve(expected);
  const std::uint64_t fingerprint = visit_coordinates(a, symmetry() == Symmetric, [&](int row, int col) {
    rows_.push_back(row + 1);
    cols_.push_back(col + 1);
  });
  coordinates_held_ = true;
  point_at_coordinates();
  return fingerprint;
}

void MumpsHandle::point_at_coordinates() {
  MUMPS_INT* rows = rows_.empty() ? nullptr : rows_.data();
  MUMPS_INT* cols = cols_.empty() ? nullptr : cols_.data();
  if (distributed()) {
    mumps_.nnz_loc = static_cast<std::int64_t>(rows_.size());
    mumps_.irn_loc = rows;
    mumps_.jcn_loc = cols;
  } else {
    mumps_.nnz = static_cast<std::int64_t>(rows_.size());
    mumps_.irn = rows;
    mumps_.jcn = cols;
  }
}

void MumpsHandle::set_pattern(const CsrMatrix& a, Symmetry symmetry) {
  if (symmetry != this->symmetry()) {
    stop();
    start(symmetry);
  }
  release_values();
  trimmed_for_pattern_ = false;
  mumps_.n = static_cast<MUMPS_INT>(a.rows());
  // The count first, so that the coordinates take exactly as much room as MUMPS is given.
  pattern_fingerprint_ = pattern_fingerprint(a, symmetry == Symmetric, pattern_entries_);
  fill_coordinates(a, pattern_entries_);
  // No values (released above): the analysis depends on the pattern only.
}

// For Symmetric, the lower triangle must match and every entry above have its mirror below.
bool MumpsHandle::has_pattern(const CsrMatrix& a) const {
  if (!a.isCompressed() || a.rows() != a.cols() || a.rows() != mumps_.n) return false;
  if (symmetry() == Symmetric)
    for (int row = 0; row < a.rows(); ++row)
      for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot) {
        const int col = a.innerIndexPtr()[slot];
        if (col > row && find_slot(a, col, row) < 0) return false;
      }
  std::size_t entries = 0;
  const std::uint64_t fingerprint = pattern_fingerprint(a, symmetry() == Symmetric, entries);
  return entries == pattern_entries_ && fingerprint == pattern_fingerprint_;
}

void MumpsHandle::set_values(const CsrMatrix& a, const Eigen::VectorXd& row_scale) {
  require(a.rows() == mumps_.n && a.isCompressed(), "MUMPS (", owner_, "): values of another pattern");
  if (!coordinates_held_) {
    // Made and checked in one pass over the pattern (a factorisation per Newton iteration pays it).
    const std::uint64_t fingerprint = fill_coordinates(a, pattern_entries_);
    const std::size_t entries = rows_.size();
    if (entries != pattern_entries_ || fingerprint != pattern_fingerprint_) {
      release_values();
      fail("MUMPS (", owner_, "): values of another pattern (", entries, " entries given, the analysed pattern has ",
           pattern_entries_, ")");
    }
  }
  // MUMPS only reads the values; its C interface is not const-correct.
  double* values = const_cast<double*>(a.valuePtr());
  if (symmetry() == Symmetric) {
    // The lower triangle in set_pattern's order, found again from the pattern rather than kept as a list
    // of slots (an int per entry, for the whole run).
    scaled_values_.resize(rows_.size());
    size_t entry = 0;  // counts every lower entry, so that one too many is refused below, not dropped
    for (int row = 0; row < a.rows(); ++row)
      for (int slot = a.outerIndexPtr()[row]; slot < a.outerIndexPtr()[row + 1]; ++slot)
        if (a.innerIndexPtr()[slot] <= row) {
          if (entry < scaled_values_.size()) scaled_values_[entry] = row_scale[row] * a.valuePtr()[slot];
          ++entry;
        }
    require(entry == scaled_values_.size(), "MUMPS (", owner_, "): values of another pattern (", entry,
            " entries in the lower triangle, the pattern has ", scaled_values_.size(), ")");
    values = scaled_values_.data();
  } else {
    require(std::size_t(a.nonZeros()) == rows_.size(), "MUMPS (", owner_, "): values of another pattern (",
            a.nonZeros(), " entries, the pattern has ", rows_.size(), ")");
  }
  (distributed() ? mumps_.a_loc : mumps_.a) = values;
}

void MumpsHandle::release_values() {
  mumps_.a = nullptr;
  mumps_.a_loc = nullptr;
  std::vector<double>().swap(scaled_values_);
  std::vector<MUMPS_INT>().swap(rows_);
  std::vector<MUMPS_INT>().swap(cols_);
  coordinates_held_ = false;
  point_at_coordinates();
}

void MumpsHandle::run(Job job, const char* phase) {
  // The run's peak of memory follows the set-up's holes at the first factorisation of a pattern; later
  // ones reuse what the last one freed, and trimming each time only made the kernel zero the same pages
  // again (5 % of a full-path run, as system time).
  if (job == Factorize && !trimmed_for_pattern_) {
    return_free_heap_pages();
    trimmed_for_pattern_ = true;
  }
  mumps_.job = job;
  dmumps_c(&mumps_);
  // INFOG is the same on every process (INFO is each one's own, -1 where another failed).
  const MUMPS_INT info1 = distributed() ? mumps_.infog[0] : mumps_.info[0];
  const MUMPS_INT info2 = distributed() ? mumps_.infog[1] : mumps_.info[1];
  if (info1 == kNumericallySingular)
    fail(owner_, ": the matrix is numerically singular (", phase, " failed with INFO(1) = ", info1,
         ", INFO(2) = ", info2, ")");
  // -13: an allocation inside MUMPS failed (-9 is a work array sized too small, which ICNTL(14) mends).
  if (info1 == -13)
    throw OutOfMemory(
        message(owner_, ": the ", phase, " ran out of memory (INFO(1) = ", info1, ", INFO(2) = ", info2, ")"));
  require(info1 >= 0, owner_, ": the ", phase, " failed with INFO(1) = ", info1, ", INFO(2) = ", info2,
          " (see the MUMPS manual)");
}

}  // namespace pc
