#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the suite with ctest.
# Usage: scripts/test.sh [release|sanitize|mpi]
#   release   (the default) the whole suite, then the build installed into a fresh prefix and
#             examples/consumer/ built and tested against it, as a user's project is (scripts/test_consumer.sh)
#   sanitize  the ASan+UBSan build: the tests labelled sanitize (tests/CMakeLists.txt lists them: the
#             engine's, the bricks' and the models' smallest) and the fuzz targets' bounded mutation runs
#   mpi       the MPI build: its distributed runs under mpirun (label mpi); it builds only what they run, as
#             the rest of the suite is the release build's with another MUMPS
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
case "$preset" in
  release | sanitize)
    scripts/install_dependencies.sh
    scripts/build.sh "$preset"
    ;;
  mpi)
    scripts/install_dependencies.sh mpi
    # OpenMPI refuses to start as root without these (CI machines run as root).
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    scripts/build.sh mpi piezocontact_cli test_distributed_runs test_distributed_model
    ;;
  *)
    echo "usage: scripts/test.sh [release|sanitize|mpi]" >&2
    exit 2
    ;;
esac
ctest --preset "$preset"
if [ "$preset" = release ]; then
  scripts/test_consumer.sh
fi
