#pragma once
// Matrix products of one column sent to the BLAS's vector routines. MUMPS's solve phase works on one
// right-hand side at a time here, and calls the level-3 routines with it: dgemm with N = 1 and dtrsm with
// one column. OpenBLAS 0.3.21 (Debian 12) packs the matrix for each such call as for a true matrix product
// (its copy routines were a quarter of the solve phase's samples on the paper's scene), where dgemv and
// dtrsv read it once; OpenBLAS forwards them itself from 0.3.27 on (GEMM_GEMV_FORWARD). This library
// defines dgemm_ and dtrsm_, which the dynamic linker binds MUMPS's calls to (the library comes before the
// BLAS in the process's lookup order): one column goes to dgemv_ / dtrsv_, everything else to the BLAS's
// own routine (dlsym RTLD_NEXT). The results are those of the BLAS contract; only the order of the
// additions differs for one column. Measured on the paper's scene at 120 x 40: solves 0.79 -> 0.61 s.
// PIEZOCONTACT_BLAS_FORWARDING=0 in the environment turns it off (every call to the BLAS's routine).
namespace pc {

// Whether the process's dgemm_ and dtrsm_ are this library's (false where a BLAS was bound before it).
bool blas_vector_forwarding_active();
// The calls sent to dgemv_ and dtrsv_ so far (to see that MUMPS's solves go through them).
long blas_vector_forwarded_calls();

}  // namespace pc
