#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the whole suite with ctest; the release
# build is then installed into a fresh prefix and examples/consumer/ is built and tested against it, as a
# user's project would be (scripts/test_consumer.sh).
# Usage: scripts/test.sh [release|sanitize|mpi]   (mpi: the MPI build, its whole suite on one process and
# its distributed runs under mpirun, label "mpi")
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
if [ "$preset" = mpi ]; then
  scripts/install_dependencies.sh mpi
  # OpenMPI refuses to start as root without these (CI machines run as root).
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
else
  scripts/install_dependencies.sh
fi
scripts/build.sh "$preset"
ctest --preset "$preset"
if [ "$preset" = release ]; then
  scripts/test_consumer.sh
fi
