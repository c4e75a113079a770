#pragma once
/// \file types.hpp
/// Scalar, index and Eigen aliases shared by every layer of symcontact.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

namespace symcontact {

using Index = std::int64_t;  ///< global indices (nodes, DOFs, cells)
using VectorXd = Eigen::VectorXd;
using MatrixXd = Eigen::MatrixXd;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;
using Vec3 = Eigen::Vector3d;

}  // namespace symcontact
