#include "symcontact/core/blas_kernels.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <string_view>

namespace symcontact {

namespace {

constexpr const char* kFallbackVariable = "SYMCONTACT_BLAS_FALLBACK";

/// OpenBLAS's x86-64 kernel families without AVX (driver/others/dynamic.c of OpenBLAS names them).
bool is_pre_avx_family(std::string_view core) {
  constexpr std::array<std::string_view, 10> families = {"Katmai", "Coppermine", "Northwood", "Prescott", "Banias",
                                                         "Core2",  "Penryn",     "Dunnington", "Nehalem", "Atom"};
  for (std::string_view f : families)
    if (core == f) return true;
  return false;
}

bool cpu_has_avx512() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
}

bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

}  // namespace

std::string blas_core_name() {
  // Looked up at run time, like blas_threads.cpp: the program also runs on the reference BLAS.
  using Getter = char* (*)();
  auto fn = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  const char* name = fn ? fn() : nullptr;
  return name ? std::string(name) : std::string();
}

std::string better_blas_core(const std::string& current) {
  if (!is_pre_avx_family(current) || !cpu_has_avx2()) return "";
  return cpu_has_avx512() ? "SkylakeX" : "Haswell";
}

void restart_with_better_blas_kernels(char** argv) {
  if (std::getenv("OPENBLAS_CORETYPE")) return;  // the user's choice, or ours already
  const std::string current = blas_core_name();
  const std::string better = better_blas_core(current);
  if (better.empty()) return;
  if (setenv("OPENBLAS_CORETYPE", better.c_str(), 1) != 0 || setenv(kFallbackVariable, current.c_str(), 1) != 0)
    return;
  execv("/proc/self/exe", argv);
  // No exec: go on with the kernels loaded, and leave the environment as it was.
  unsetenv("OPENBLAS_CORETYPE");
  unsetenv(kFallbackVariable);
}

std::string blas_kernel_note() {
  const char* fallback = std::getenv(kFallbackVariable);
  const char* chosen = std::getenv("OPENBLAS_CORETYPE");
  if (!fallback || !chosen) return "";
  return std::string("OpenBLAS chose its ") + fallback + " kernels, which do not use this CPU's " +
         (std::string_view(chosen) == "SkylakeX" ? "AVX-512" : "AVX2") + "; running with OPENBLAS_CORETYPE=" + chosen;
}

}  // namespace symcontact
