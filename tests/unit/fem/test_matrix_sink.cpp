#include "symcontact/fem/matrix_sink.hpp"

#include <gtest/gtest.h>

using namespace symcontact;

TEST(MatrixSink, ReducedSinkKeepsLowerTriangleOfFreeBlock) {
  // 3 DOFs, DOF 1 fixed: K_ff is the (0, 2) block.
  const double K[9] = {4, 1, 2, 1, 5, 3, 2, 3, 6};  // symmetric, column-major
  const Index dofs[3] = {0, 1, 2};
  std::vector<Index> free_index = {0, -1, 1};
  ReducedTripletSink r(free_index);
  r.add(dofs, 3, K);
  r.add(dofs, 3, K);
  const SparseMatrix A = r.to_lower_matrix(2);
  EXPECT_DOUBLE_EQ(A.coeff(0, 0), 8.0);
  EXPECT_DOUBLE_EQ(A.coeff(1, 0), 4.0);
  EXPECT_DOUBLE_EQ(A.coeff(0, 1), 0.0);  // upper triangle not stored
  EXPECT_DOUBLE_EQ(A.coeff(1, 1), 12.0);
  TripletSink t;
  t.add(dofs, 3, K);
  const SparseMatrix F = t.to_matrix(3);
  EXPECT_DOUBLE_EQ(F.coeff(1, 2), 3.0);
  EXPECT_DOUBLE_EQ(F.coeff(2, 1), 3.0);
}

TEST(MatrixSink, ZeroEntriesOfABlockStayInThePattern) {
  // A block with exact zeros (a tangent at a symmetric state): the assembled matrices still hold those
  // entries, so that their pattern is the structural one, the same at every state (ipopt_solver.hpp
  // fixes the Hessian pattern at x0).
  const double K[9] = {4, 0, 2, 0, 5, 0, 2, 0, 6};  // column-major, (1, 0), (2, 1) and their mirrors zero
  const Index dofs[3] = {0, 1, 2};
  std::vector<Index> free_index = {0, 1, 2};
  ReducedTripletSink r(free_index);
  r.add(dofs, 3, K);
  const SparseMatrix A = r.to_lower_matrix(3);
  EXPECT_EQ(A.nonZeros(), 6);  // the whole lower triangle
  EXPECT_DOUBLE_EQ(A.coeff(1, 0), 0.0);
  TripletSink t;
  t.add(dofs, 3, K);
  EXPECT_EQ(t.to_matrix(3).nonZeros(), 9);
}
