// The thread settings (src/symcontact/core/blas_threads.hpp): on one thread no OpenMP region is active, so that
// CHOLMOD's supernodal factorisation, which asks for its own thread count, runs on the calling thread.
#include "symcontact/core/blas_threads.hpp"

#include <dlfcn.h>

#include <gtest/gtest.h>

namespace symcontact {
namespace {

int max_active_levels() {
  using Getter = int (*)();
  // libgomp comes with CHOLMOD, which this binary links.
  const auto get = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  return get ? get() : -1;
}

TEST(BlasThreads, OneThreadLeavesNoOpenMpRegionActive) {
  set_openmp_threads(2);
  EXPECT_EQ(max_active_levels(), 1);
  set_openmp_threads(1);
  EXPECT_EQ(max_active_levels(), 0);
}

}  // namespace
}  // namespace symcontact
