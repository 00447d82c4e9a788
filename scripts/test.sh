#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs the whole suite with ctest; the release
# build is then installed into a fresh prefix and examples/consumer/ is built and tested against it, as a
# user's project would be (scripts/test_consumer.sh).
# Usage: scripts/test.sh [release|sanitize]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
scripts/install_dependencies.sh
scripts/build.sh "$preset"
ctest --preset "$preset"
if [ "$preset" = release ]; then
  scripts/test_consumer.sh
fi
