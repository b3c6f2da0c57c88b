#include "modal/ModalSuperposition.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

namespace flexehd::modal {

Eigen::MatrixXd heldBasis(const ReducedBody& body, const std::vector<int>& held) {
    const Eigen::Index m = body.numModes();
    // Constraint A q = 0 (held reference motions); q = N r with N an orthonormal null-space basis.
    Eigen::MatrixXd A(6 * held.size(), m);
    for (std::size_t i = 0; i < held.size(); ++i) {
        if (held[i] < 0 || held[i] >= int(body.interfaces.size()))
            throw std::invalid_argument("held interfaces: interface " + std::to_string(held[i]) + " does not exist");
        A.middleRows<6>(6 * i) = body.interfaceMotion.middleRows<6>(6 * held[i]);
    }
    if (A.rows() == 0) return Eigen::MatrixXd::Identity(m, m);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A.transpose());
    const Eigen::Index r = qr.rank();
    return (qr.householderQ() * Eigen::MatrixXd::Identity(m, m)).rightCols(m - r);
}

ModalSuperposition::ModalSuperposition(const ReducedBody& body) : body_(body) {}

Eigen::VectorXd ModalSuperposition::displacement(const Eigen::VectorXd& q) const { return body_.shapes * q; }

Eigen::Matrix3Xd ModalSuperposition::displacementAt(const std::vector<fem::Index>& nodes,
                                                    const Eigen::VectorXd& q) const {
    Eigen::Matrix3Xd u(3, nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) u.col(k) = body_.shapes.middleRows<3>(3 * nodes[k]) * q;
    return u;
}

Eigen::VectorXd ModalSuperposition::modalForce(const Eigen::VectorXd& f) const {
    if (f.size() != body_.shapes.rows())
        throw std::invalid_argument("modal force: " + std::to_string(f.size()) + " nodal force entries, body has " +
                                    std::to_string(body_.shapes.rows()) + " DOFs");
    return body_.shapes.transpose() * f;
}

Eigen::LDLT<Eigen::MatrixXd> heldStiffness(const ReducedBody& body, const Eigen::MatrixXd& N) {
    Eigen::LDLT<Eigen::MatrixXd> ldlt(N.transpose() * body.stiffnessMatrix * N);
    const double scale = body.stiffnessMatrix.diagonal().cwiseAbs().maxCoeff();
    if (ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 1e-10 * scale)
        throw std::runtime_error("the body can still move rigidly with its held interfaces; hold an interface "
                                 "that fixes it");
    return ldlt;
}

Eigen::VectorXd heldFrequenciesHz(const ReducedBody& body, const std::vector<int>& held) {
    const Eigen::MatrixXd N = heldBasis(body, held);
    if (N.cols() == 0) return Eigen::VectorXd();
    (void)heldStiffness(body, N);  // throws if the held body can move rigidly
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(N.transpose() * body.stiffnessMatrix * N,
                                                                        N.transpose() * body.massMatrix * N,
                                                                        Eigen::EigenvaluesOnly);
    if (eig.info() != Eigen::Success) throw std::runtime_error("the held body's frequencies could not be computed");
    return eig.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);
}

double normalModesUpToHz(const ReducedBody& body) {
    const ReductionSettings& s = body.settings;
    if (s.cutoffHz > 0.0) return s.cutoffHz;
    if (s.normalModes <= 0) return 0.0;
    std::vector<int> all(body.interfaces.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    const Eigen::VectorXd f = all.empty() ? body.frequenciesHz : heldFrequenciesHz(body, all);
    if (f.size() == 0) return 0.0;
    return f(std::min<Eigen::Index>(s.normalModes, f.size()) - 1);
}

Eigen::VectorXd ModalSuperposition::quasiStatic(const Eigen::VectorXd& g, const std::vector<int>& held) const {
    const Eigen::Index m = body_.numModes();
    if (g.size() != m)
        throw std::invalid_argument("quasi-static: " + std::to_string(g.size()) + " modal forces for " +
                                    std::to_string(m) + " modes");
    const Eigen::MatrixXd N = heldBasis(body_, held);
    if (N.cols() == 0) return Eigen::VectorXd::Zero(m);  // held interfaces fix every mode
    return N * heldStiffness(body_, N).solve(N.transpose() * g);
}

Eigen::MatrixXd ModalSuperposition::compliance(const std::vector<int>& held) const {
    const Eigen::Index m = body_.numModes();
    const Eigen::MatrixXd N = heldBasis(body_, held);
    if (N.cols() == 0) return Eigen::MatrixXd::Zero(m, m);  // held interfaces fix every mode
    return N * heldStiffness(body_, N).solve(N.transpose());
}

ModalDynamics::ModalDynamics(const ReducedBody& body, double dt) : dt_(dt) {
    if (!(dt > 0.0)) throw std::invalid_argument("modal dynamics: time step must be > 0 s");
    if (body.supportDamping.size() > 0)
        throw std::invalid_argument("modal dynamics: the body's damper supports couple its modes, which this "
                                    "mode-by-mode integration cannot carry; use HeldModalDynamics or ModalPropagator");
    const Eigen::Index m = body.numModes();
    omega2_ = body.stiffnessMatrix.diagonal();
    c_.resize(m);
    for (Eigen::Index k = 0; k < m; ++k) c_(k) = 2.0 * body.dampingRatios(k) * std::sqrt(std::max(omega2_(k), 0.0));
    q_ = v_ = a_ = Eigen::VectorXd::Zero(m);
}

void ModalDynamics::setState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& f) {
    q_ = q;
    v_ = v;
    a_ = f - c_.cwiseProduct(v_) - omega2_.cwiseProduct(q_);
}

void ModalDynamics::step(const Eigen::VectorXd& f) {
    // Newmark β = 1/4, γ = 1/2 per mode: (ω² + 2c/Δt + 4/Δt²) q₊ = f₊ + ...
    const double h = dt_;
    for (Eigen::Index k = 0; k < q_.size(); ++k) {
        const double keff = omega2_(k) + 2.0 * c_(k) / h + 4.0 / (h * h);
        const double rhs = f(k) + (4.0 / (h * h)) * q_(k) + (4.0 / h) * v_(k) + a_(k) +
                           c_(k) * ((2.0 / h) * q_(k) + v_(k));
        const double qn = rhs / keff;
        const double vn = (2.0 / h) * (qn - q_(k)) - v_(k);
        a_(k) = (4.0 / (h * h)) * (qn - q_(k)) - (4.0 / h) * v_(k) - a_(k);
        q_(k) = qn;
        v_(k) = vn;
    }
}

}  // namespace flexehd::modal
