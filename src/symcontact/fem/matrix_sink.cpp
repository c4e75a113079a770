#include "symcontact/fem/matrix_sink.hpp"

namespace symcontact {

void TripletSink::add(const Index* dofs, int n, const double* K) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triplets_.emplace_back(static_cast<int>(dofs[i]), static_cast<int>(dofs[j]), K[i + j * n]);
    }
}

SparseMatrix TripletSink::to_matrix(Index n) const {
  SparseMatrix A(n, n);
  A.setFromTriplets(triplets_.begin(), triplets_.end());
  return A;
}

void ReducedTripletSink::add(const Index* dofs, int n, const double* K) {
  for (int j = 0; j < n; ++j) {
    const Index fj = free_index_[dofs[j]];
    if (fj < 0) continue;
    for (int i = 0; i < n; ++i) {
      const Index fi = free_index_[dofs[i]];
      if (fi < fj) continue;  // fixed (−1) or upper triangle
      triplets_.emplace_back(static_cast<int>(fi), static_cast<int>(fj), K[i + j * n]);
    }
  }
}

SparseMatrix ReducedTripletSink::to_lower_matrix(Index num_free) const {
  SparseMatrix A(num_free, num_free);
  A.setFromTriplets(triplets_.begin(), triplets_.end());
  return A;
}

void DenseLowerSink::add(const Index* dofs, int n, const double* K) {
  for (int j = 0; j < n; ++j) {
    const Index bj = index_[dofs[j]];
    if (bj < 0) continue;
    for (int i = 0; i < n; ++i) {
      const Index bi = index_[dofs[i]];
      if (bi < bj) continue;  // not a row (−1) or upper triangle
      data_[bi + bj * m_] += s_ * K[i + j * n];
    }
  }
}

void ProductSink::add(const Index* dofs, int n, const double* K) {
  for (int i = 0; i < n; ++i) {
    const Index bi = index_[dofs[i]];
    if (bi < 0) continue;
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
      const Index bj = index_[dofs[j]];
      if (bj >= 0) sum += K[i + j * n] * v_[bj];
    }
    out_[bi] += sum;
  }
}

}  // namespace symcontact
