#pragma once
// Hands the heap's free pages back to the system (glibc's malloc_trim; nothing elsewhere). A run's set-up
// allocates and frees millions of small blocks (patterns built row by row, patch fits), and the holes they
// leave below the heap's top stay resident: glibc trims only the top. Called before the run's peak of
// memory, MUMPS's factorisation, so that the peak is the live data and the factorisation's own arrays,
// not the set-up's holes besides (paper's scene at 240 x 80: 185 -> 178 MB). MumpsHandle calls it before
// the first factorisation of each pattern only: the pages it returns are faulted in and zeroed again by
// the next allocations, which cost 5 % of a run that factorises at every Newton iteration.
namespace pc {

void return_free_heap_pages();

}  // namespace pc
