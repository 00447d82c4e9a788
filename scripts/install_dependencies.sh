#!/usr/bin/env bash
# Installs the Debian 12 packages piezocontact needs; does nothing when all are present.
# Usage: scripts/install_dependencies.sh [mpi] [ccache] [format]   (mpi: also OpenMPI and the MPI build of
# MUMPS; ccache: also ccache, which the build uses when it is there; format: clang-format, for
# scripts/check_format.sh)
# Run as root (or with sudo available).
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libmumps-seq-dev libgmsh-dev nlohmann-json3-dev zlib1g-dev libmetis-dev libspectra-dev
  libopenblas0-serial liblapack-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy
)
for extra in "$@"; do
  case "$extra" in
    mpi) packages+=(libmumps-dev libopenmpi-dev openmpi-bin) ;;
    ccache) packages+=(ccache) ;;
    format) packages+=(clang-format) ;;
    *) echo "install_dependencies.sh: unknown extra '$extra' (known: mpi, ccache, format)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
