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
  /// With the factor's interior columns I (the first n − |B|) and y in the factor's order: y_I ← L_II⁻¹ y_I
  /// (interior_forward), y_I ← L_II⁻ᵀ (y_I − L_BIᵀ y_B) (interior_backward), y_B unchanged. The supernodes of B
  /// (the dense trailing block L_BB, often most of the factor's entries) are not read.
  void interior_forward(VectorXd& y) const;
  void interior_backward(VectorXd& y) const;
};

}  // namespace symcontact
