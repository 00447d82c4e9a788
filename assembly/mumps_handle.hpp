#pragma once
// Internal to the MUMPS back ends (solver_mumps.cpp, schur_complement.cpp): one MUMPS instance, silenced
// (errors become pc::Error naming the phase and INFO), and the matrix handed over as MUMPS's 1-based
// coordinates: whole, for an LU factorisation, or the lower triangle of a row-scaled matrix that is
// symmetric (assembly/symmetrizing_scale.hpp), for LDL^T.
// A local instance works on this process alone (MPI_COMM_SELF in the MPI build). A distributed one spans
// every process (assembly/processes.hpp): each gives its share of the matrix, entries that the processes
// sum (MUMPS's distributed assembled input, ICNTL(18) = 3), and the right-hand side and the solution are
// whole on the host, rank 0.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <dmumps_c.h>

#include "assembly/sparse.hpp"

namespace pc {

class MumpsHandle {
 public:
  enum Job : MUMPS_INT { Analyze = 1, Factorize = 2, Solve = 3 };
  // MUMPS's SYM: general (LU) or general symmetric (LDL^T with 2x2 pivots, indefinite matrices allowed).
  enum Symmetry : MUMPS_INT { General = 0, Symmetric = 2 };

  enum Scope { Local, Distributed };

  explicit MumpsHandle(const char* owner, Scope scope = Local);
  ~MumpsHandle();
  MumpsHandle(const MumpsHandle&) = delete;
  MumpsHandle& operator=(const MumpsHandle&) = delete;

  DMUMPS_STRUC_C& operator*() { return mumps_; }
  DMUMPS_STRUC_C* operator->() { return &mumps_; }
  MUMPS_INT& icntl(int i) { return mumps_.icntl[i - 1]; }  // 1-based, as in the MUMPS manual

  // Points MUMPS at the pattern of `a` (row and column indices kept here), without values: all of it, or
  // its lower triangle for Symmetric (the pattern of `a` must then be symmetric). SYM is fixed when a MUMPS
  // instance starts, so a change of symmetry starts a new one: every ICNTL the owner set is then back at
  // its default (set them after this call).
  void set_pattern(const CsrMatrix& a, Symmetry symmetry = General);
  Symmetry symmetry() const { return Symmetry(mumps_.sym); }
  bool distributed() const { return scope_ == Distributed; }
  // Whether `a` has the pattern last given to set_pattern (so that a caller need keep no copy to compare).
  bool has_pattern(const CsrMatrix& a) const;
  // Points MUMPS at the values of `a` (same pattern as set_pattern's): `a`'s own array in General mode;
  // for Symmetric, the lower triangle of diag(row_scale) a, copied here until release_values(). The
  // coordinates are made again from `a` if release_values() dropped them.
  void set_values(const CsrMatrix& a, const Eigen::VectorXd& row_scale);
  // Forgets the values and the coordinates (an analysis or a factorisation reads them; the solves need
  // only the factors). Kept with the factors for the whole run, the coordinates were an int pair per
  // entry: 5 MB at the paper's 240 x 80, at the run's peak of memory. What stays is the pattern's
  // fingerprint, which has_pattern and set_values compare.
  void release_values();
  // Runs a job; throws pc::Error naming the owner and the phase on failure (numerically singular
  // matrices get their own message).
  void run(Job job, const char* phase);

 private:
  void start(Symmetry symmetry);
  void stop();
  // Fills rows_ and cols_ with the coordinates MUMPS is given for `a` (all, or the lower triangle; room
  // for `expected` made first), points MUMPS at them, and returns their fingerprint.
  std::uint64_t fill_coordinates(const CsrMatrix& a, std::size_t expected);
  void point_at_coordinates();

  const char* owner_;
  Scope scope_;
  DMUMPS_STRUC_C mumps_{};
  std::vector<MUMPS_INT> rows_, cols_;  // empty between release_values() and set_values()
  bool coordinates_held_ = false;
  std::size_t pattern_entries_ = 0;
  std::uint64_t pattern_fingerprint_ = 0;
  bool trimmed_for_pattern_ = false;  // the heap was trimmed before a factorisation of this pattern
  std::vector<double> scaled_values_;
};

}  // namespace pc
