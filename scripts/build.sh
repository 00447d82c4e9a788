#!/usr/bin/env bash
# Configures (once) and builds a CMake preset; later runs rebuild only what changed.
# Usage: scripts/build.sh [release|sanitize] [ninja targets...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
shift || true
[ -f "build/$preset/build.ninja" ] || cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -- "$@"
