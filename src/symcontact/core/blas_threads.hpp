#pragma once
/// \file blas_threads.hpp
/// The number of threads of the BLAS that CHOLMOD and MUMPS call. Debian's OpenBLAS (pthread build)
/// spins its worker threads while waiting (sched_yield), which on a busy or small machine costs more
/// than it gains for the supernodal blocks of 2D contact problems; symcontact therefore runs it on one
/// thread unless asked otherwise (CLI --threads, or OPENBLAS_NUM_THREADS in the environment).
/// The OpenMP thread count (CHOLMOD's parallel regions) is set along: on one thread they run on the calling
/// thread (set_openmp_threads). CHOLMOD's supernodal factorisation otherwise wakes four OpenMP threads per
/// large supernode: on a 2-core machine the futex wake-ups and waits cost about as much as the factorisation
/// itself (docs/performance.md, "Machine"). With a BLAS other than OpenBLAS the BLAS calls do nothing.

namespace symcontact {

/// Sets OpenBLAS's thread count when OpenBLAS is the BLAS in use; returns false otherwise. OpenMP's follows.
bool set_blas_threads(int threads);

/// OpenMP's thread count; with 1, no parallel region is active (CHOLMOD's included).
void set_openmp_threads(int threads);

/// The setting of `--threads` (the command line, the Python API, the benchmarks): `threads` > 0 that many
/// threads; 0 OpenBLAS's count from OPENBLAS_NUM_THREADS where the environment sets it, else 1; OpenMP's
/// follows OpenBLAS's.
void apply_thread_setting(int threads);

/// The thread count OpenBLAS reports, or −1 when OpenBLAS is not the BLAS in use.
int blas_threads();

}  // namespace symcontact
