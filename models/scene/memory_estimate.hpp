#pragma once
// What a run of a generated mesh will need, estimated before the mesh is built, so that a scene that
// cannot fit is refused at once with the estimate named instead of growing until std::bad_alloc.
// The bytes per dof are the measured peaks of whole runs (benchmarks/cost_growth_study: 6.7 KiB per dof
// for P1 and 8.0 for P2 in 2D, sparse factorisation included), with a margin; 3D factorisations fill in
// far more and are budgeted at 32 KiB per dof. An estimate, not a bound: it errs on the large side, the
// more so since the model keeps one copy of its data (peaks measured since: 4.8 KiB per dof for P1 at
// 232k dofs, 5.7 for P2 at 58.6k), which leaves the budgets as they were until the study is rerun.
namespace pc {

struct MemoryEstimate {
  double dofs = 0;   // unknowns of v and phi
  double bytes = 0;  // peak of a run
};

// A structured mesh of cells[0] x ... x cells[dim - 1] cells of order `order`.
MemoryEstimate estimate_structured_run(int dim, const int* cells, int order);
// The memory this process may still use: what the machine has available now (MemAvailable of
// /proc/meminfo), or less under an address-space limit (ulimit -v) or a cgroup's memory.max; 0 when unknown.
double available_memory_bytes();

}  // namespace pc
