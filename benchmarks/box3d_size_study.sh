#!/usr/bin/env bash
# What a 3D run costs as it grows: the 3D box (scenes/box3d.json, insulated foundation, the scene's step of
# 4 ms) on gmsh tetrahedra in P1 and P2 and on generated hexahedra in Q1, a few steps each, every run a
# fresh process under /usr/bin/time. Per run: dofs, contact dofs, the linear strategy auto chose, Newton
# iterations, wall time per step, the phases (models/scene/run_timing.hpp), and the peak resident memory,
# also per dof. Writes OUT/box3d_sizes.csv row by row and prints a markdown table at the end.
#   benchmarks/box3d_size_study.sh [runner = build/release/examples/piezocontact] [out = results/box3d_sizes]
#                                  [steps = 5] [cases = all | a comma-separated list of case names]
# The largest cases (p1_0.13: 548k dofs, p2_0.25, q1_96: 422k dofs) take minutes each and up to 20 GB.
set -euo pipefail
cd "$(dirname "$0")/.."
runner=$(realpath "${1:-build/release/examples/piezocontact}")
out=${2:-results/box3d_sizes}
steps=${3:-5}
only=${4:-all}
mkdir -p "$out"
step_size=0.004
end_time=$(python3 -c "print($steps * $step_size)")
hex_regions='regions={"clamped":["xmin"],"traction":["ymax"],"contact":"ymin","grounded":["ymax"],"charge":["xmax"]}'
hex_mesh() {  # nx: the box (0,0.03) x (0,0.01) x (0,0.01) in nx x nx/3 x nx/3 hexahedra
  echo "mesh={\"generator\":\"box\",\"x\":[0,0.03],\"y\":[0,0.01],\"z\":[0,0.01],\"nx\":$1,\"ny\":$(($1 / 3)),\"nz\":$(($1 / 3)),\"cell\":\"hexahedron\",\"order\":1}"
}
cases=("p1_0.5|--set mesh.size_factor=0.5"
       "p1_0.25|--set mesh.size_factor=0.25"
       "p1_0.13|--set mesh.size_factor=0.13"
       "p2_1.0|--set mesh.size_factor=1.0 --set mesh.order=2"
       "p2_0.5|--set mesh.size_factor=0.5 --set mesh.order=2"
       "p2_0.35|--set mesh.size_factor=0.35 --set mesh.order=2"
       "p2_0.25|--set mesh.size_factor=0.25 --set mesh.order=2"
       "q1_30|--set $(hex_mesh 30) --set $hex_regions --set loads.traction[0].region=ymax"
       "q1_60|--set $(hex_mesh 60) --set $hex_regions --set loads.traction[0].region=ymax"
       "q1_96|--set $(hex_mesh 96) --set $hex_regions --set loads.traction[0].region=ymax")
csv=$out/box3d_sizes.csv
[ -f "$csv" ] || echo "case,dofs,contact_dofs,strategy,steps,newton_iterations,wall_s,wall_per_step_s,peak_rss_mb,rss_kb_per_dof,assembly_residual_s,assembly_jacobian_s,factorize_s,solve_s,condensation_s,output_s,other_s,factorizations" > "$csv"
for c in "${cases[@]}"; do
  name=${c%%|*}; args=${c#*|}
  [ "$only" = all ] || [[ ",$only," == *",$name,"* ]] || continue
  echo "== $name" >&2
  # shellcheck disable=SC2086  # the arguments are split on purpose (each JSON value has no spaces)
  if ! /usr/bin/time -f "%M" -o "$out/$name.rss" "$runner" run scenes/box3d.json --only insulated --quiet \
      --out "$out/$name" --set time.steps="$steps" --set time.T="$end_time" --set output.vtu_every="$steps" $args \
      > "$out/$name.log" 2>&1; then
    echo "$name: the run failed (see $out/$name.log)" >&2
    continue
  fi
  python3 - "$out/$name/insulated/summary.json" "$out/$name.rss" "$name" "$steps" >> "$csv" <<'PY'
import json, re, sys
summary, rss_file, name, steps = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
s = json.load(open(summary))
rss_kb = int(open(rss_file).read().split()[-1])
t = s["timing"]
m = re.search(r"(\d+) contact dofs", s.get("linear_strategy", ""))
strategy = s.get("linear_strategy", "").rsplit(": ", 1)[-1]
print(",".join(str(x) for x in [name, s["ndof"], m.group(1) if m else "", strategy, s["steps"],
      s["newton_iterations_total"], round(s["wall_s_total"], 2), round(s["wall_s_total"] / max(s["steps"], 1), 3),
      round(rss_kb / 1024), round(rss_kb / s["ndof"], 2), *(round(t[k], 2) for k in
      ("assembly_residual_s", "assembly_jacobian_s", "factorize_s", "solve_s", "condensation_s", "output_s",
       "other_s")), t["factorizations"]]))
PY
done
python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| case | dofs | contact dofs | strategy | Newton its / steps | per step | peak RSS | per dof | factorise | solve | condensation | assembly |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    assembly = float(r["assembly_residual_s"]) + float(r["assembly_jacobian_s"])
    print(f"| {r['case']} | {int(r['dofs']):,} | {r['contact_dofs']} | {r['strategy']} | {r['newton_iterations']} / {r['steps']} "
          f"| {float(r['wall_per_step_s']):.2f} s | {int(r['peak_rss_mb']):,} MB | {float(r['rss_kb_per_dof']):.1f} kB "
          f"| {r['factorize_s']} s ({r['factorizations']}) | {r['solve_s']} s | {r['condensation_s']} s | {assembly:.2f} s |")
PY
