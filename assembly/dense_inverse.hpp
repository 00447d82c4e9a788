#pragma once
// The inverse of a square dense matrix, by LAPACK's LU with partial pivoting (dgetrf, dgecon, dgetri),
// which Debian's alternatives resolve to OpenBLAS's blocked kernels: at the 3D box's 1176 contact dofs
// three times faster than Eigen's PartialPivLU and inverse() (0.09 against 0.28 s on this machine), the
// same to round-off.
#include <optional>

#include <Eigen/Core>

namespace pc {

// The inverse of `a` when its distance to the singular matrices, as LAPACK's 1-norm condition estimate
// gives it (rcond * ||a||_1, about the smallest singular value), exceeds `smallest`; nothing for a matrix
// closer to singular (a zero pivot included) or an inverse that is not finite.
std::optional<Eigen::MatrixXd> inverse_if_regular(Eigen::MatrixXd a, double smallest);

}  // namespace pc
