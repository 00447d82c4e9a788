#!/usr/bin/env bash
# Generates the API reference with Doxygen (docs/Doxyfile): the public headers of assembly/, bricks/ and
# models/, with docs/api.md as the main page, into build/api/html/index.html. Installs doxygen from the
# Debian packages when it is missing (as scripts/install_dependencies.sh does); run as root or with sudo.
# Usage: scripts/api_docs.sh
set -euo pipefail
cd "$(dirname "$0")/.."

if ! dpkg-query -W -f='${Status}' doxygen 2>/dev/null | grep -q "install ok installed"; then
  echo "installing: doxygen"
  as_root=()
  [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  # Refresh the package lists only when they do not know doxygen (a fresh machine has none).
  if ! apt-cache policy doxygen 2>/dev/null | grep -q "Candidate: [0-9]"; then
    "${as_root[@]}" apt-get update -qq
  fi
  "${as_root[@]}" apt-get install -y -qq --no-install-recommends doxygen
fi

mkdir -p build/api
doxygen docs/Doxyfile
echo "API reference: build/api/html/index.html"
