// Tests run in parallel under ctest: keep OpenBLAS on one thread per test process (core/blas_threads.hpp).
#include <cstdlib>

#include "symcontact/core/blas_threads.hpp"

namespace {
const bool kSingleThreadBlas = [] {
  symcontact::apply_thread_setting(0);
  return true;
}();
}  // namespace
