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

/// One supernode of CHOLMOD's supernodal factor (cholmod_factor, is_super): columns k1 … k2 − 1, its rows
/// (the first k2 − k1 are those columns, then the rest ascending), its entries column-major, nrows × (k2 − k1).
struct Supernode {
  Index k1, k2, nrows;
  const CholmodIndex* rows;
  const double* x;
};

inline Supernode supernode(const cholmod_factor& f, Index k) {
  const auto* super = static_cast<const CholmodIndex*>(f.super);
  const auto* pi = static_cast<const CholmodIndex*>(f.pi);
  const auto* px = static_cast<const CholmodIndex*>(f.px);
  const auto* s = static_cast<const CholmodIndex*>(f.s);
  return {super[k], super[k + 1], pi[k + 1] - pi[k], s + pi[k], static_cast<const double*>(f.x) + px[k]};
}

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
