// Tests run in parallel under ctest: keep OpenBLAS on one thread per test process (core/blas_threads.hpp).
#include <cstdlib>

#include "symcontact/core/blas_threads.hpp"

namespace {
const bool kSingleThreadBlas = [] {
  if (!std::getenv("OPENBLAS_NUM_THREADS")) symcontact::set_blas_threads(1);
  return true;
}();
}  // namespace
