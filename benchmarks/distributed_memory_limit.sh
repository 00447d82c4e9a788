#!/usr/bin/env bash
# A run that one process cannot make within a memory limit and two processes can: the same scene on 1 and
# on 2 MPI processes, each process under the same address-space limit (ulimit -v, inherited by every
# process mpirun starts). Prints each run's exit status and its last line: the single process stops with
# MUMPS's out-of-memory error (INFO(1) = -13, the run's manifest says "stopped"), the pair completes.
#   benchmarks/distributed_memory_limit.sh [runner = build/mpi/examples/piezocontact] [limit KiB = 1200000]
#                                          [out = results/distributed_memory_limit]
# The default case: the 3D box at 84k P1 dofs, 5 steps, full factorisations (1.1 GB on one process,
# 0.76 GB on each of two).
set -uo pipefail
cd "$(dirname "$0")/.."
runner=$(realpath "${1:-build/mpi/examples/piezocontact}")
limit=${2:-1200000}
out=${3:-results/distributed_memory_limit}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PIEZOCONTACT_THREADS=1
args=(run scenes/box3d.json --only insulated --quiet --no-sweep --set time.steps=5 --set time.T=0.02
      --set mesh.size_factor=0.25 --set solver.condensed=false)
for processes in 1 2; do
  rm -rf "$out/np$processes"
  status=$( (ulimit -v "$limit"; mpirun -np "$processes" "$runner" "${args[@]}" --out "$out/np$processes" \
             > "$out.np$processes.log" 2>&1; echo $?) )
  said=$(grep -h -m1 -E "STOPPED|error" "$out.np$processes.log" || grep -h '"completed"' "$out/np$processes"/*/summary.json)
  echo "$processes process(es), ulimit -v $limit KiB each: exit $status: $said"
done
