#pragma once
/// \file cholmod_long.hpp
/// The one index type symcontact hands to CHOLMOD: its 64-bit interface (cholmod_l_*, SuiteSparse_long),
/// at every size. Used by CholeskySolver (through Eigen's CholmodSupport, which calls cholmod_l_* when the
/// matrix's StorageIndex is SuiteSparse_long) and by StaticCondensation (CHOLMOD called directly).
///
/// Why: CHOLMOD's int interface indexes the factor's values with int, so it fails once the supernodal
/// factor holds 2³¹ entries or more ("problem too large" in cholmod_super_symbolic). For 3D P1 elasticity
/// that happens near 1e6 DOFs (nnz(L) ∝ N^1.4: 3.6e8 at 2.9e5 DOFs, about 2e9 at 1e6; docs/performance.md).
/// The long interface has no such limit; what it costs (the matrix's index arrays copied to 64 bits, and
/// 64-bit row indices in the symbolic factor) is small next to the factor's 8 bytes per value.
///
/// The stiffness matrices themselves stay SparseMatrix (int indices): their nonzeros are 10–100 times
/// fewer than the factor's, far from 2³¹ at any size that can be factorised in memory.

#include <cholmod.h>

#include <Eigen/SparseCore>

#include "symcontact/core/types.hpp"

namespace symcontact {

using CholmodIndex = SuiteSparse_long;
/// A compressed column matrix with CHOLMOD's long indices.
using CholmodSparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, CholmodIndex>;

/// `lower` (int indices) copied with long indices, compressed.
inline CholmodSparseMatrix to_cholmod_long(const SparseMatrix& lower) {
  CholmodSparseMatrix a = lower;
  a.makeCompressed();
  return a;
}

/// A CHOLMOD view (no copy) of the lower triangle of a compressed matrix with long indices.
inline cholmod_sparse view_lower(const CholmodSparseMatrix& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<CholmodIndex*>(A.outerIndexPtr());
  s.i = const_cast<CholmodIndex*>(A.innerIndexPtr());
  s.nz = nullptr;
  s.x = const_cast<double*>(A.valuePtr());
  s.z = nullptr;
  s.stype = -1;  // symmetric, lower triangle stored
  s.itype = CHOLMOD_LONG;  // cholmod_l_* throughout (cholmod_long.hpp)
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

/// A CHOLMOD view (no copy) of a vector.
inline cholmod_dense view_vector(VectorXd& v) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(v.size());
  d.ncol = 1;
  d.nzmax = static_cast<size_t>(v.size());
  d.d = static_cast<size_t>(v.size());
  d.x = v.data();
  d.z = nullptr;
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace symcontact
