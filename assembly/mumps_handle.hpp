#pragma once
// Internal to the MUMPS back ends (solver_mumps.cpp, schur_complement.cpp): one sequential MUMPS instance
// in general unsymmetric (LU) mode, silenced (errors become pc::Error naming the phase and INFO), and
// the matrix pattern handed over as MUMPS's 1-based coordinates.
#include <vector>

#include <dmumps_c.h>

#include "assembly/sparse.hpp"

namespace pc {

class MumpsHandle {
 public:
  enum Job : MUMPS_INT { Analyze = 1, Factorize = 2, Solve = 3 };

  explicit MumpsHandle(const char* owner);
  ~MumpsHandle();
  MumpsHandle(const MumpsHandle&) = delete;
  MumpsHandle& operator=(const MumpsHandle&) = delete;

  DMUMPS_STRUC_C& operator*() { return mumps_; }
  DMUMPS_STRUC_C* operator->() { return &mumps_; }
  MUMPS_INT& icntl(int i) { return mumps_.icntl[i - 1]; }  // 1-based, as in the MUMPS manual

  // Points MUMPS at the pattern of `a` (row and column indices kept here), without values.
  void set_pattern(const CsrMatrix& a);
  // Whether `a` has the pattern last given to set_pattern (so that a caller need keep no copy to compare).
  bool has_pattern(const CsrMatrix& a) const;
  // Runs a job; throws pc::Error naming the owner and the phase on failure (numerically singular
  // matrices get their own message).
  void run(Job job, const char* phase);

 private:
  const char* owner_;
  DMUMPS_STRUC_C mumps_{};
  std::vector<MUMPS_INT> rows_, cols_;
};

}  // namespace pc
