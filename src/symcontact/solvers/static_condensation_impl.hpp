#pragma once
/// \file static_condensation_impl.hpp
/// StaticCondensation's state (static_condensation.hpp), shared by its two files: static_condensation.cpp
/// (compute() and the solves with the factor) and static_condensation_factor.cpp (the ordering, the factor of
/// the augmented matrix and the Schur complement read from it).

#include <algorithm>
#include <string>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholmod_long.hpp"
#include "symcontact/solvers/dense_kkt.hpp"
#include "symcontact/solvers/static_condensation.hpp"

namespace symcontact {

struct StaticCondensation::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  Index n = 0;
  std::vector<Index> boundary;
  std::vector<Index> position;  ///< index → position in B or −1
  std::vector<CholmodIndex> perm;  ///< the ordering handed to CHOLMOD (interior first, B last)
  SparseMatrix schur;
  SparseMatrix k;  ///< K (lower)

  Impl() {
    cholmod_l_start(&common);
    common.print = 0;  // failures are reported through status and exceptions
  }
  ~Impl() {
    release();
    cholmod_l_finish(&common);
  }
  void release() {
    if (factor) cholmod_l_free_factor(&factor, &common);
    factor = nullptr;
  }
  std::vector<Index> interior_ordering(const SparseMatrix& lower, Index ni);
  VectorXd factorise_augmented(const SparseMatrix& lower);
  void extract_schur(const SparseMatrix& lower, const VectorXd& d, Index ni);
  void store_schur(const AlignedMatrix& u, const VectorXd& d);
  /// x ← solution of `sys` (CHOLMOD_L or CHOLMOD_Lt, no permutation) with right-hand side x.
  void triangular_solve(int sys, VectorXd& x) {
    cholmod_dense b = view_vector(x);
    cholmod_dense* y = cholmod_l_solve(sys, factor, &b, &common);
    if (!y) throw SolveError("CHOLMOD triangular solve failed (status " + std::to_string(common.status) + ")");
    std::copy_n(static_cast<const double*>(y->x), x.size(), x.data());
    cholmod_l_free_dense(&y, &common);
  }
};

}  // namespace symcontact
