#!/usr/bin/env bash
# Which BLAS the solvers should call, by measurement: the same runs of the paper's scene (conductive
# foundation, no sweep) and of the 3D box, each under the reference BLAS, OpenBLAS (serial) and BLIS
# (serial), chosen per run through LD_LIBRARY_PATH so that one hyperfine session compares them; then the
# results of each against the reference's (summary.json numbers, relative difference).
#   benchmarks/blas_comparison.sh [runner = build/release/examples/piezocontact] [out = results/blas]
# Needs hyperfine and Debian's libopenblas0-serial and libblis4-serial (scripts/install_dependencies.sh
# installs OpenBLAS; BLIS by hand).
set -euo pipefail
cd "$(dirname "$0")/.."
runner=$(realpath "${1:-build/release/examples/piezocontact}")
out=${2:-results/blas}
mkdir -p "$out"
lib=/usr/lib/x86_64-linux-gnu
declare -A blas=([reference]=$lib/blas [openblas]=$lib/openblas-serial [blis]=$lib/blis-serial)
cases=("paper2d_120x40|scenes/paper2d.json --only conductive --no-sweep --set mesh.nx=120 --set mesh.ny=40"
       "paper2d_240x80|scenes/paper2d.json --only conductive --no-sweep --set mesh.nx=240 --set mesh.ny=80"
       "box3d_0.5|scenes/box3d.json --only conductive --set mesh.size_factor=0.5")
for c in "${cases[@]}"; do
  name=${c%%|*}; args=${c#*|}
  commands=()
  for b in reference openblas blis; do
    [ -e "${blas[$b]}/libblas.so.3" ] || continue
    commands+=(-n "$b" "LD_LIBRARY_PATH=${blas[$b]} $runner run $args --quiet --out $out/$name-$b")
  done
  hyperfine --runs 3 --export-markdown "$out/$name.md" "${commands[@]}"
  python3 - "$out" "$name" <<'PY'
import json, sys, os
out, name = sys.argv[1], sys.argv[2]
ref = json.load(open(f"{out}/{name}-reference/conductive/summary.json"))
for b in ("openblas", "blis"):
    path = f"{out}/{name}-{b}/conductive/summary.json"
    if not os.path.exists(path): continue
    s = json.load(open(path))
    worst = max(abs(s[k] - ref[k]) / max(abs(ref[k]), 1e-300) for k in ref
                if isinstance(ref[k], float) and not k.startswith("wall") and k in s and isinstance(s[k], float))
    print(f"{name}: {b} against reference: largest relative difference of the summary's results {worst:.2e}")
PY
done
