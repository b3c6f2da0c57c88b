#include "cosim/coupling/IqnIlsAccelerator.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace flexehd::cosim {

IqnIlsAccelerator::IqnIlsAccelerator(double initialRelaxation, int maxColumns)
    : omega0_(initialRelaxation), maxColumns_(maxColumns) {}

void IqnIlsAccelerator::reset() {
    first_ = true;
    V_.clear();
    W_.clear();
}

Eigen::VectorXd IqnIlsAccelerator::next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) {
    const Eigen::VectorXd r = Hy - y;
    if (first_) {
        first_ = false;
        lastR_ = r;
        lastH_ = Hy;
        return y + omega0_ * r;
    }
    // Newest column first, at most maxColumns_.
    V_.insert(V_.begin(), r - lastR_);
    W_.insert(W_.begin(), Hy - lastH_);
    if (int(V_.size()) > maxColumns_) {
        V_.pop_back();
        W_.pop_back();
    }
    lastR_ = r;
    lastH_ = Hy;
    for (;;) {
        const Eigen::Index n = Eigen::Index(V_.size());
        Eigen::MatrixXd V(r.size(), n);
        for (Eigen::Index i = 0; i < n; ++i) V.col(i) = V_[std::size_t(i)];
        Eigen::HouseholderQR<Eigen::MatrixXd> qr(V);
        const Eigen::MatrixXd R = qr.matrixQR().topRows(n).triangularView<Eigen::Upper>();
        // Filter: drop the oldest column while a diagonal of R is tiny relative to the largest.
        double rmax = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) rmax = std::max(rmax, std::abs(R(i, i)));
        bool dependent = false;
        for (Eigen::Index i = 0; i < n; ++i)
            if (!(std::abs(R(i, i)) > 1e-10 * rmax)) dependent = true;
        if (dependent && n > 1) {
            V_.pop_back();
            W_.pop_back();
            continue;
        }
        if (dependent) {  // a single vanishing column: no model, relaxed step
            V_.clear();
            W_.clear();
            return y + omega0_ * r;
        }
        const Eigen::VectorXd c = qr.solve(Eigen::VectorXd(-r));
        Eigen::VectorXd out = Hy;
        for (Eigen::Index i = 0; i < n; ++i) out += c[i] * W_[std::size_t(i)];
        return out;
    }
}

}  // namespace flexehd::cosim
