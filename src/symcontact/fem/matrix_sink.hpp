#pragma once
/// \file matrix_sink.hpp
/// Where assembled element matrices go (STYLE.md §3: kernel, assembly and storage are separate).
/// A kernel fills a dense n × n block for the global DOFs `dofs[0..n)`; a sink stores it.
///  - TripletSink: Eigen triplets in global numbering (duplicates summed later by setFromTriplets).
///  - ReducedTripletSink: drops the rows/columns of fixed DOFs and renumbers the free ones, keeping
///    only the lower triangle — the form a Cholesky factorisation of K_ff wants.
///  - DenseLowerSink, ProductSink: the same renumbering, the blocks added (scaled) into the lower triangle of a
///    dense matrix, or multiplied with a vector, with no matrix stored (the condensed problem's surface terms).
/// Both keep every entry of every block, zeros included: the pattern of the assembled matrix is the
/// structural one of the element connectivity, the same at every state. An entry that happens to be
/// zero at one state (a Neo-Hookean tangent at u = 0 on a symmetric element) is nonzero at the next,
/// and a solver that fixes the pattern at its first evaluation (IPOPT, ipopt_solver.hpp) needs it.

#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

class MatrixSink {
 public:
  virtual ~MatrixSink() = default;
  /// Adds the n × n column-major block `K` at rows/columns `dofs`.
  virtual void add(const Index* dofs, int n, const double* K) = 0;
};

class TripletSink : public MatrixSink {
 public:
  void add(const Index* dofs, int n, const double* K) override;
  std::vector<Triplet>& triplets() { return triplets_; }
  /// Builds a square sparse matrix of size `n` (duplicates summed).
  SparseMatrix to_matrix(Index n) const;

 private:
  std::vector<Triplet> triplets_;
};

class ReducedTripletSink : public MatrixSink {
 public:
  /// `free_index[dof]` is the DOF's index among the free DOFs, or −1 if it is fixed.
  explicit ReducedTripletSink(const std::vector<Index>& free_index) : free_index_(free_index) {}
  void add(const Index* dofs, int n, const double* K) override;
  std::vector<Triplet>& triplets() { return triplets_; }
  /// The lower triangle of K_ff, of size num_free.
  SparseMatrix to_lower_matrix(Index num_free) const;

 private:
  const std::vector<Index>& free_index_;
  std::vector<Triplet> triplets_;
};

/// Adds s K into the lower triangle of the dense column-major m × m matrix at `data` (leading dimension m), at
/// the positions index[dof] (−1: not a row of the matrix; the block's entries there are dropped).
class DenseLowerSink : public MatrixSink {
 public:
  DenseLowerSink(const std::vector<Index>& index, double s, double* data, Index m)
      : index_(index), s_(s), data_(data), m_(m) {}
  void add(const Index* dofs, int n, const double* K) override;

 private:
  const std::vector<Index>& index_;
  double s_;
  double* data_;
  Index m_;
};

/// out += K v for every block K, rows and columns mapped by index[dof] as in DenseLowerSink.
class ProductSink : public MatrixSink {
 public:
  ProductSink(const std::vector<Index>& index, const VectorXd& v, VectorXd& out) : index_(index), v_(v), out_(out) {}
  void add(const Index* dofs, int n, const double* K) override;

 private:
  const std::vector<Index>& index_;
  const VectorXd& v_;
  VectorXd& out_;
};

}  // namespace symcontact
