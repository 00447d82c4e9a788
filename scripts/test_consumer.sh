#!/usr/bin/env bash
# The installed package as a user meets it: installs the release build into a fresh prefix, then builds
# and tests examples/consumer/ (a driver, a plugin, GoogleTest cases, the runner on a scene naming the
# plugin) against that prefix only, from outside the source tree.
# Usage: scripts/test_consumer.sh   (after scripts/build.sh release)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install build/release --prefix "$work/prefix" >/dev/null
cp -r examples/consumer "$work/consumer"
cmake -S "$work/consumer" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DPIEZOCONTACT_SCENES="$PWD/scenes" >/dev/null
cmake --build "$work/build"
ctest --test-dir "$work/build" --output-on-failure
