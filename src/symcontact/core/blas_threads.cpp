#include "symcontact/core/blas_threads.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>

namespace symcontact {

void set_openmp_threads(int threads) {
  using Setter = void (*)(int);
  // Looked up at run time: libgomp is loaded by CHOLMOD (and Gmsh), not by this library.
  if (auto omp = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "omp_set_num_threads"))) omp(threads);
  // CHOLMOD's supernodal factorisation asks for CHOLMOD_OMP_NUM_THREADS threads (4 in Debian's SuiteSparse 5.12,
  // cholmod_core.h) in a num_threads clause, whatever omp_set_num_threads says. With no active level allowed
  // (OpenMP 5.2 §2.6.1: a region beyond max-active-levels-var is inactive) its regions run on the calling
  // thread alone.
  if (auto levels = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
    levels(threads > 1 ? 1 : 0);
}

// OpenBLAS exports these C functions (openblas_config.h); looked up at run time so that the program also
// runs, unchanged, on the reference BLAS.
bool set_blas_threads(int threads) {
  using Setter = void (*)(int);
  set_openmp_threads(threads);
  auto fn = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!fn) return false;
  fn(threads);
  return true;
}

int blas_threads() {
  using Getter = int (*)();
  auto fn = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return fn ? fn() : -1;
}

void apply_thread_setting(int threads) {
  if (threads > 0)
    set_blas_threads(threads);
  else if (!std::getenv("OPENBLAS_NUM_THREADS"))
    set_blas_threads(1);
  else
    set_openmp_threads(std::max(1, blas_threads()));
}

}  // namespace symcontact
