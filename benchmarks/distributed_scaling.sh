#!/usr/bin/env bash
# Strong scaling of a distributed run on this machine: the same scene on 1 and 2 MPI processes (one thread
# each) and on 1 process with 2 threads, each a fresh `mpirun` under /usr/bin/time, so that every process's
# peak resident memory is measured. Per run: processes, threads, dofs, wall time of the run, the phases
# (summary.json), the largest and the summed peak memory of its processes, and MUMPS's own prediction of
# its memory (INFOG(16), INFOG(17): the largest process, all; with solver.condensed=false).
# Writes OUT/distributed_scaling.csv and prints it as a markdown table.
#   benchmarks/distributed_scaling.sh [runner = build/mpi/examples/piezocontact] [out = results/distributed_scaling]
#                                     [scene = scenes/box3d.json] [runner arguments ...]
# e.g. benchmarks/distributed_scaling.sh build/mpi/examples/piezocontact results/ds scenes/box3d.json \
#        --only insulated --set time.steps=5 --set time.T=0.02 --set mesh.size_factor=0.35
set -euo pipefail
cd "$(dirname "$0")/.."
runner=$(realpath "${1:-build/mpi/examples/piezocontact}")
out=${2:-results/distributed_scaling}
scene=${3:-scenes/box3d.json}
shift 3 2>/dev/null || shift $#
extra=("$@")
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
csv=$out/distributed_scaling.csv
echo "processes,threads,dofs,wall_s,factorize_s,solve_s,assembly_residual_s,peak_rss_mb_max,peak_rss_mb_sum,mumps_mb_largest,mumps_mb_all" > "$csv"
for config in "1 1" "2 1" "1 2"; do
  read -r processes threads <<< "$config"
  run=$out/np${processes}_t${threads}
  rm -rf "$run" && mkdir -p "$run"
  echo "== $processes processes x $threads threads" >&2
  # Each process under its own /usr/bin/time, its file named by its rank.
  # shellcheck disable=SC2016  # expanded by the inner shell, per process
  PIEZOCONTACT_THREADS=$threads mpirun -np "$processes" --oversubscribe \
    sh -c 'exec /usr/bin/time -f "%M" -o "$0/rss.$OMPI_COMM_WORLD_RANK" "$@"' "$run" \
    "$runner" run "$scene" --quiet --no-sweep --out "$run/out" "${extra[@]}" >&2
  python3 - "$run" "$processes" "$threads" >> "$csv" <<'PY'
import glob, json, sys
run, processes, threads = sys.argv[1:]
rss = [int(open(f).read().split()[-1]) / 1024 for f in glob.glob(run + "/rss.*")]
summaries = [json.load(open(f)) for f in sorted(glob.glob(run + "/out/*/summary.json"))]
total = lambda key: sum(s["timing"].get(key, 0) for s in summaries)
factors = summaries[0].get("factorization", {})  # MUMPS's INFOG(16), INFOG(17): full factorisations only
print(f"{processes},{threads},{summaries[0]['ndof']},{sum(s['wall_s_total'] for s in summaries):.3f},"
      f"{total('factorize_s'):.3f},{total('solve_s'):.3f},{total('assembly_residual_s'):.3f},{max(rss):.0f},{sum(rss):.0f},"
      f"{factors.get('memory_mb_largest_process', 0):.0f},{factors.get('memory_mb_all_processes', 0):.0f}")
PY
done
python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
print("| " + " | ".join(rows[0]) + " |")
print("|" + "---|" * len(rows[0]))
for r in rows[1:]:
    print("| " + " | ".join(r) + " |")
PY
