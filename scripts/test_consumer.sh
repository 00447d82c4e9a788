#!/usr/bin/env bash
# The installed package as a user meets it: installs the release build into a fresh prefix, then builds
# and tests examples/consumer/ (a driver, two plugins, GoogleTest cases, the runner on scenes naming the
# plugins; the README's and docs' blocks of a law, its test and its CMakeLists are regions of these files)
# against that prefix only, from outside the source tree.
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
# --no-tests=error: a project whose CMakeLists lost enable_testing() has no tests, and ctest would pass.
ctest --test-dir "$work/build" --output-on-failure --no-tests=error
echo "consumer project: built and tested against the package in ${SECONDS} s"

# Code written against 0.1.0's header paths still compiles against the package, each old path saying
# where its header went.
cmake -S tests/consumer/old_includes -B "$work/old_includes" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/old_includes" 2>&1 | tee "$work/old_includes.log" | tail -1
"$work/old_includes/old_includes"
notes=$(grep -c "moved to .* in 0.2.0; include the new path" "$work/old_includes.log" || true)
[ "$notes" -ge 10 ] || { echo "old includes: expected a note for each of the 10 moved headers, got $notes"; exit 1; }
echo "old includes: compiled, ran, and each moved header said where it went"
