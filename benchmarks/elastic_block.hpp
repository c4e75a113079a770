#pragma once
/// \file elastic_block.hpp
/// The benchmark problem: a linear-elastic unit square (plane strain) or unit cube on a structured
/// simplex mesh (rectangle_mesh / box_mesh), clamped on its bottom face (y = 0, resp. z = 0) and
/// loaded by a uniform pressure p on its top face (traction t = −p n). E = 1, ν = 0.3, p = 10⁻³.
///
/// And its "Cholesky floor": the time of one assembly and one sparse Cholesky factor-and-solve of
/// K_ff u_f = f_f. The contact benchmark reports its solve time as a multiple of this floor, so the
/// floor is measured here once and in one way.

#include <memory>
#include <stdexcept>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/energy/linear_elastic_energy.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/mesh/mesh.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"
#include "symcontact/solvers/memory_prediction.hpp"  // available_memory_bytes, predict_factor_nonzeros

namespace symcontact::bench {

/// Number of DOFs of the block with `divisions` squares/cubes per side: dim · (order·n + 1)^dim.
Index block_dofs(int dim, int order, int divisions);
/// The number of divisions per side whose DOF count is nearest to `target_dofs` (at least 1).
int block_divisions(int dim, int order, double target_dofs);

/// The assembled problem. Not copyable or movable (the energy refers to the mesh).
class ElasticBlock {
 public:
  ElasticBlock(int dim, int order, int divisions);
  ElasticBlock(const ElasticBlock&) = delete;
  ElasticBlock& operator=(const ElasticBlock&) = delete;

  int dim, order, divisions;
  double mesh_seconds = 0.0;   ///< rectangle_mesh / box_mesh
  double setup_seconds = 0.0;  ///< Dirichlet numbering, load vector, energy construction
  Mesh mesh;
  DofMap dofs;
  FixedDofs fixed;                ///< every component of every node of the bottom face, = 0
  std::vector<Index> free_index;  ///< FixedDofs::free_numbering()
  Index num_free = 0;
  VectorXd load_free;             ///< f_f, the pressure load restricted to the free DOFs

  const LinearElasticEnergy& energy() const { return *energy_; }

 private:
  std::unique_ptr<LinearElasticEnergy> energy_;
};

/// One assembly and one Cholesky factor-and-solve of K_ff u_f = f_f, each phase the minimum over
/// `repeat` runs (a fresh factorisation every run; the previous factor is freed first).
struct CholeskyFloor {
  double assembly = 0.0;   ///< add_hessian into a ReducedTripletSink + to_lower_matrix(), s
  double gradient = 0.0;   ///< one add_gradient(u, g) of the elastic energy over all DOFs, s
  double analyze = 0.0;    ///< CHOLMOD ordering + symbolic factorisation, s
  double factorize = 0.0;  ///< CHOLMOD numeric factorisation, s
  double solve = 0.0;      ///< forward and back substitution for one right-hand side, s
  Index num_triplets = 0;  ///< entries the sink received (lower triangle of K_ff, duplicates kept)
  Index nnz_lower = 0;     ///< stored entries of the lower triangle of K_ff
  Index nnz_full = 0;      ///< nonzeros of the full symmetric K_ff (2·nnz_lower − n)
  double nnz_factor = 0.0; ///< nonzeros of L (CHOLMOD's count, diagonal included)
  double relative_residual = 0.0;  ///< ‖K_ff u_f − f_f‖ / ‖f_f‖
  double max_displacement = 0.0;   ///< max |u_f|, a sanity check that the load went in
  double cpu_factor_and_solve = 0.0;  ///< process CPU time of analyze + factorize + solve, s (min over runs)
  /// What a contact solve is compared with: analyze + factorize + solve.
  double factor_and_solve() const { return analyze + factorize + solve; }
};

/// Thrown by measure_cholesky_floor() right after the analysis, and by check_factor_fits(), when the
/// predicted factor does not fit in memory, instead of failing or swapping in factorize(). (CHOLMOD's
/// 64-bit interface, cholmod_long.hpp, has no 2³¹ limit on the factor's entries: memory is the limit.)
class FactorTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};


/// Throws FactorTooLarge when a factor of `nnz_factor` entries (8 bytes each) plus `other_bytes` needs
/// more than MemAvailable.
void check_factor_fits(double nnz_factor, double other_bytes = 0.0);


CholeskyFloor measure_cholesky_floor(const ElasticBlock& block, int repeat);

/// The same measurement for any energy whose Hessian does not depend on u (K = ∇²E(0)): K_ff is
/// assembled over the DOFs with free_index[d] ≥ 0 (num_free of them, free_index has num_dofs entries)
/// and solved for `load_free`. Throws SolveError when K_ff is not positive definite.
CholeskyFloor measure_cholesky_floor(const EnergyTerm& energy, const std::vector<Index>& free_index, Index num_free,
                                     const VectorXd& load_free, int repeat);

}  // namespace symcontact::bench
