#pragma once
// Tall dense products of the reduction (basis vectors x a hundred columns) through the
// system BLAS (dgemm; OpenBLAS: vectorised, multithreaded): Eigen's built-in kernel is
// compiled for baseline SSE2 and single-threaded, and these products are several GFlop.
#include <Eigen/Core>

namespace flexehd::modal {

/// Aᵀ B.
Eigen::MatrixXd multiplyTransposed(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);
/// A B.
Eigen::MatrixXd multiply(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

}  // namespace flexehd::modal
