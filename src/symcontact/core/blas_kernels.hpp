#pragma once
/// \file blas_kernels.hpp
/// The kernel family of OpenBLAS, and a better one where OpenBLAS does not know the CPU.
///
/// Debian's OpenBLAS is built for every x86-64 kernel family (DYNAMIC_ARCH) and picks one when it is
/// loaded, from the CPU's family and model numbers. A CPU newer than its table (OpenBLAS 0.3.21 of Debian
/// 12 on a 5th-generation Xeon, family 6 model 207) falls back to Prescott, its SSE3 kernels, although the
/// CPU has AVX-512: the dense Schur complements, CHOLMOD's supernodes and MUMPS's fronts then run 1.5–2
/// times slower (docs/performance.md, "Machine"). The family is read from OPENBLAS_CORETYPE when the
/// library is loaded, i.e. before main(); a program that wants another one sets it and starts again
/// (restart_with_better_blas_kernels()). The choice is by instruction set, as OpenBLAS's own for the CPUs it
/// knows: SkylakeX with AVX-512 (F, CD, BW, DQ, VL), Haswell with AVX2 and FMA. The kernels differ only in
/// round-off (tests/zoo: OpenBlasKernels).

#include <string>

namespace symcontact {

/// The kernel family OpenBLAS uses ("Haswell", "SkylakeX", "Prescott", ...), or "" when the BLAS is not
/// OpenBLAS.
std::string blas_core_name();

/// The family this CPU can run that is better than `current`, when `current` is one of the families
/// without AVX (OpenBLAS's fallback for a CPU it does not know) and the CPU has AVX2: "SkylakeX" or
/// "Haswell". Otherwise "".
std::string better_blas_core(const std::string& current);

/// When OPENBLAS_CORETYPE is unset and better_blas_core(blas_core_name()) names a family: sets
/// OPENBLAS_CORETYPE to it, and SYMCONTACT_BLAS_FALLBACK to the family OpenBLAS had chosen, and replaces
/// the process by a new run of the same program with the same arguments (execv of /proc/self/exe). Returns
/// only when it does nothing or the exec fails. Call it first in main(), before any other work.
void restart_with_better_blas_kernels(char** argv);

/// After such a restart, one line for the log: "OpenBLAS chose its Prescott kernels, which do not use this
/// CPU's AVX-512; running with OPENBLAS_CORETYPE=SkylakeX". "" otherwise.
std::string blas_kernel_note();

}  // namespace symcontact
