#pragma once
// How many threads the element loops (TermAssembly) and the residual's sparse products (Model) use.
// The default is the environment variable PIEZOCONTACT_THREADS if it is set, else the cores available
// (shared among the processes of a distributed run);
// set_assembly_threads() overrides both (a scene's solver.threads). Results do not depend on the count:
// elements are computed in parallel and added into the global arrays in element order, and products
// are computed row by row with their norms summed in row order, as one thread does, so that a run on
// several threads is bitwise equal to a run on one.
// Terms are therefore called concurrently on different elements: Term::assemble must not change state
// shared between elements (it is const; the built-in terms and loads keep none).
namespace pc {

int assembly_threads();
// threads >= 1; 0 goes back to the default. Eigen's parallel products (Eigen::setNbThreads) follow it.
void set_assembly_threads(int threads);
// The threads of Eigen's parallel products inside the libraries (Eigen::nbThreads() as they see it: they
// are built with OpenMP, a caller may not be, and Eigen then answers 1 in the caller's code).
int eigen_product_threads();
// The default: PIEZOCONTACT_THREADS (an integer >= 1, else pc::Error naming it and its value), or the
// cores available divided by the processes of the run (at least 1).
int default_assembly_threads();

}  // namespace pc
