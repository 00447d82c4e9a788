#!/usr/bin/env bash
# Writes the registry tables of docs/scenes.md from the registries (piezocontact describe --markdown).
# Usage: scripts/update_docs.sh [path/to/piezocontact]
set -euo pipefail
cd "$(dirname "$0")/.."
runner=${1:-build/release/examples/piezocontact}
tables=$("$runner" describe --markdown)
python3 - "$tables" <<'PY'
import re, sys
path = "docs/scenes.md"
text = open(path).read()
begin, end = "<!-- registry:begin", "<!-- registry:end -->"
head = text[:text.index(begin)]
marker = text[text.index(begin):text.index("-->", text.index(begin)) + 3]
tail = text[text.index(end):]
open(path, "w").write(head + marker + "\n" + sys.argv[1].strip("\n") + "\n" + tail)
PY
