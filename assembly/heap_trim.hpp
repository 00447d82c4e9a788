#pragma once
// Hands the heap's free pages back to the system (glibc's malloc_trim; nothing elsewhere). A run's set-up
// allocates and frees millions of small blocks (patterns built row by row, patch fits), and the holes they
// leave below the heap's top stay resident: glibc trims only the top. Called before the run's peak of
// memory, MUMPS's factorisation, so that the peak is the live data and the factorisation's own arrays,
// not the set-up's holes besides (paper's scene at 240 x 80: 185 -> 178 MB). Its cost is a walk over the
// free lists, about a millisecond, at each factorisation.
namespace pc {

void return_free_heap_pages();

}  // namespace pc
