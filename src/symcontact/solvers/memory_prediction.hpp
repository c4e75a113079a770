#pragma once
/// \file memory_prediction.hpp
/// What the serial solver's sparse factors will need, before they are computed: CHOLMOD's symbolic analysis
/// of K_ff predicts nnz(L) (assembly and ordering only: seconds where the factorisation takes minutes), and
/// a model of the contact solve's peak memory built on it. `symcontact run` chooses the distributed path
/// from it (app/linear_solver_choice.hpp); the benchmarks refuse a size that cannot fit.

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/energy/energy_term.hpp"

namespace symcontact {

/// MemAvailable of /proc/meminfo in bytes, or −1 where it cannot be read.
double available_memory_bytes();

/// nnz(L) and the flops of factorising K_ff, the energy's Hessian at 0 on the DOFs with free_index[d] ≥ 0, as
/// CHOLMOD's analysis predicts them.
struct FactorPrediction {
  double nonzeros = 0.0, flops = 0.0;
};
FactorPrediction predict_factor(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free);
/// predict_factor()'s nonzeros.
double predict_factor_nonzeros(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free);

/// CHOLMOD's supernodal factor stores more than nnz(L) entries: the zeros of relaxed supernode amalgamation
/// and the upper triangles of the diagonal blocks. L->xsize / nnz(L) on the 3D Hertz K_ff: 1.235 at
/// 2.0e5 DOFs, 1.218 at 1.07e6 (docs/performance.md).
inline constexpr double kFactorStorage = 1.25;
/// Mesh, model, K and its copies, vectors: fitted (below).
inline constexpr double kBytesPerDof = 5632.0;
/// The m × m dense matrices of the condensed contact problem (S's lower triangle, its pivoted Cholesky
/// factor, W = A S⁺ Aᵀ and the interior point's factor; during the condensation L_BB and S): fitted as below
/// (25; 73–84 with IPOPT on the dual, whose MUMPS factorised the dense W as a sparse matrix).
inline constexpr double kDenseBytesPerEntry = 25.0;

/// The serial contact solve's peak memory in bytes,
///     kFactorStorage · 8 · nnz(L) + kBytesPerDof · DOFs + kDenseBytesPerEntry · m²,
/// the factor of the static condensation (the same matrix with the contact DOFs ordered last, whose nnz(L)
/// is within a few per cent of K_ff's) in CHOLMOD's supernodal storage, the mesh, model and sparse matrices,
/// and the dense condensed problem, m the number of contact-surface nodes. The two coefficients are fitted to
/// the peak RSS of the 3D Hertz solve: 3,276, 8,369 and 20,406 MiB at 2.0e5, 4.1e5 and 7.8e5 DOFs (m = 3,282,
/// 5,224 and 7,978), against 3,488, 8,800 and 20,367 predicted.
double predicted_direct_peak_bytes(double factor_nonzeros, double dofs, double contact_nodes);

}  // namespace symcontact
