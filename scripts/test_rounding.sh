#!/usr/bin/env bash
# The rounding stage (issue 44): the unit-labelled tests of the release build again, on another family of
# OpenBLAS kernels than the one the suite just ran on. A test whose assertion moves with the last digits
# (a step count, an iteration number) then fails on every machine, not only on the kind whose default
# kernels happen to round that way. Bitwise comparisons between two runs in one stage still hold: both
# runs use the same kernels.
# Usage: scripts/test_rounding.sh [CORE]   (after scripts/test.sh release; CORE: an OPENBLAS_CORETYPE
# name, by default Prescott, or Haswell where the suite ran on Prescott)
set -euo pipefail
cd "$(dirname "$0")/.."
runner=build/release/examples/piezocontact
current=$("$runner" --version | sed -n 's/^BLAS: OpenBLAS (core \([^,]*\),.*/\1/p')
if [ -z "$current" ]; then
  echo "rounding stage skipped: the BLAS is not OpenBLAS ($("$runner" --version | sed -n 's/^BLAS: //p'))"
  exit 0
fi
other=${1:-Prescott}
[ "${current,,}" != "${other,,}" ] || other=Haswell
export OPENBLAS_CORETYPE=$other
echo "rounding stage: the suite ran on OpenBLAS's $current kernels; now the unit tests on $other"
"$runner" --version
ctest --preset release -L unit
