#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the whole suite with ctest.
# Usage: scripts/test.sh [release|sanitize]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
scripts/install_dependencies.sh
scripts/build.sh "$preset"
ctest --preset "$preset"
