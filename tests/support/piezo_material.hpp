#pragma once
// Test support: the paper scene's PZT-5H tensors (plane strain, poled along y) scaled to order one, so
// that manufactured solutions exercise the anisotropic coupled operator with a well-conditioned system.
#include <Eigen/Core>

namespace pc::testing {

struct PiezoTensors {
  Eigen::MatrixXd A, B, E, beta;
};

inline PiezoTensors scaled_pzt5h() {
  PiezoTensors t;
  t.B.resize(3, 3);
  t.B << 1.27205, 0.846702, 0, 0.846702, 1.17436, 0, 0, 0, 0.229885;
  t.A = 0.1 * t.B;
  t.E.resize(2, 3);
  t.E << 0, 0, 0.170345, -0.0662281, 0.232403, 0;
  t.beta.resize(2, 2);
  t.beta << 1.5091, 0, 0, 1.2693;
  return t;
}

// Voigt index of the symmetric pair (i, j) in 2D: xx 0, yy 1, xy 2.
inline int voigt_index_2d(int i, int j) { return i == j ? i : 2; }

}  // namespace pc::testing
