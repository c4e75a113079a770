#include "symcontact/core/blas_threads.hpp"

#include <dlfcn.h>

namespace symcontact {

// OpenBLAS exports these C functions (openblas_config.h); looked up at run time so that the program also
// runs, unchanged, on the reference BLAS.
bool set_blas_threads(int threads) {
  using Setter = void (*)(int);
  // CHOLMOD (SuiteSparse) is built with OpenMP: its thread count follows the same setting.
  if (auto omp = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "omp_set_num_threads"))) omp(threads);
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

}  // namespace symcontact
