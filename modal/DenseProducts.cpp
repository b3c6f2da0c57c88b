#include "modal/DenseProducts.hpp"

#include <stdexcept>

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace flexehd::modal {
namespace {
Eigen::MatrixXd gemm(char ta, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
    const int m = static_cast<int>(ta == 'T' ? A.cols() : A.rows());
    const int k = static_cast<int>(ta == 'T' ? A.rows() : A.cols());
    if (k != B.rows()) throw std::invalid_argument("dense product: inner dimensions differ");
    const int n = static_cast<int>(B.cols());
    Eigen::MatrixXd C(m, n);
    if (m == 0 || n == 0) return C;
    if (k == 0) return C.setZero();
    const double one = 1.0, zero = 0.0;
    const int lda = static_cast<int>(A.rows()), ldb = static_cast<int>(B.rows());
    const char tb = 'N';
    dgemm_(&ta, &tb, &m, &n, &k, &one, A.data(), &lda, B.data(), &ldb, &zero, C.data(), &m);
    return C;
}
}  // namespace

Eigen::MatrixXd multiplyTransposed(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) { return gemm('T', A, B); }
Eigen::MatrixXd multiply(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) { return gemm('N', A, B); }

}  // namespace flexehd::modal
