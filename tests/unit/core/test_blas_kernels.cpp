// OpenBLAS's kernel family and the better one where OpenBLAS fell back to kernels without AVX
// (src/symcontact/core/blas_kernels.hpp).

#include "symcontact/core/blas_kernels.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <string>

namespace symcontact {
namespace {

TEST(BlasKernels, OnlyFamiliesWithoutAvxAreReplacedAndOnlyOnCpusWithAvx2) {
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const std::string better = better_blas_core("Prescott");
  EXPECT_EQ(better.empty(), !avx2);
  if (avx2) {
    EXPECT_TRUE(better == "SkylakeX" || better == "Haswell") << better;
  }
  if (avx2 && !__builtin_cpu_supports("avx512f")) {
    EXPECT_EQ(better, "Haswell");
  }
  EXPECT_EQ(better_blas_core("Nehalem"), better);  // every pre-AVX family alike
  EXPECT_EQ(better_blas_core("Core2"), better);
  for (const char* kept : {"Haswell", "SkylakeX", "Cooperlake", "Zen", "Sandybridge", ""})
    EXPECT_EQ(better_blas_core(kept), "") << kept;
}

TEST(BlasKernels, TheLoadedFamilyIsTheOneOpenBlasReportsInItsConfiguration) {
  using Getter = char* (*)();
  auto config = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
  if (!config) GTEST_SKIP() << "the BLAS in use is not OpenBLAS";
  const std::string core = blas_core_name();
  ASSERT_FALSE(core.empty());
  EXPECT_NE(std::string(config()).find(" " + core + " "), std::string::npos) << config();
  EXPECT_EQ(blas_kernel_note(), "") << "a test process is never restarted";
}

}  // namespace
}  // namespace symcontact
