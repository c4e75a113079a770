#pragma once
/// \file blas_threads.hpp
/// The number of threads of the BLAS that CHOLMOD and MUMPS call. Debian's OpenBLAS (pthread build)
/// spins its worker threads while waiting (sched_yield), which on a busy or small machine costs more
/// than it gains for the supernodal blocks of 2D contact problems; symcontact therefore runs it on one
/// thread unless asked otherwise (CLI --threads, or OPENBLAS_NUM_THREADS in the environment).
/// The OpenMP thread count (CHOLMOD) is set along. With a BLAS other than OpenBLAS these calls do nothing.

namespace symcontact {

/// Sets OpenBLAS's thread count when OpenBLAS is the BLAS in use; returns false otherwise.
bool set_blas_threads(int threads);

/// The thread count OpenBLAS reports, or −1 when OpenBLAS is not the BLAS in use.
int blas_threads();

}  // namespace symcontact
