#pragma once
// OpenBLAS (the BLAS that MUMPS calls, scripts/install_dependencies.sh) allocates its work buffer at the
// first matrix-matrix product and keeps it for the later ones; when that first allocation fails, it
// retries for ever instead of failing. A run whose memory is nearly used up when MUMPS first factorises
// would hang there (seen under `ulimit -v`). reserve_blas_workspace() makes that first product at once,
// while memory is plentiful, so that a later shortage ends in the clean out-of-memory error of MUMPS or of
// the model. Once per process; run_scene() calls it before anything is built. When even the buffer cannot
// be had (memory already short: an MPI build's processes map much of their address space at start), it
// throws OutOfMemory rather than make the first product, which would hang.
namespace pc {

void reserve_blas_workspace();

}  // namespace pc
