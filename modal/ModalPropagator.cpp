#include "modal/ModalPropagator.hpp"

#include "modal/ModalDamping.hpp"
#include "modal/ModalSuperposition.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::modal {
namespace {

using Complex = std::complex<double>;

// φ₃(z) = (eᶻ − 1 − z − z²/2)/z³, by its series Σ zᵏ/(k+3)! where the closed form cancels.
Complex phi3(Complex z) {
    if (std::abs(z) < 0.5) {
        Complex term = 1.0 / 6.0, sum = term;
        for (int k = 1; k < 14; ++k) sum += (term *= z / double(k + 3));
        return sum;
    }
    return (std::exp(z) - 1.0 - z - 0.5 * z * z) / (z * z * z);
}

// φ₁(z) = (eᶻ − 1)/z and φ₂(z) = (eᶻ − 1 − z)/z²; by their series Σ zᵏ/(k+1)!, Σ zᵏ/(k+2)! where
// the closed forms cancel (|z| < ½: 14 terms leave less than 1e-16).
void phi(Complex z, Complex& phi1, Complex& phi2) {
    if (std::abs(z) < 0.5) {
        Complex term1 = 1.0, term2 = 0.5;
        phi1 = term1;
        phi2 = term2;
        for (int k = 1; k < 14; ++k) {
            term1 *= z / double(k + 1);
            term2 *= z / double(k + 2);
            phi1 += term1;
            phi2 += term2;
        }
        return;
    }
    const Complex e = std::exp(z);
    phi1 = (e - 1.0) / z;
    phi2 = (e - 1.0 - z) / (z * z);
}

}  // namespace

ModalPropagator::ModalPropagator(const ReducedBody& body, const std::vector<int>& held) {
    const Eigen::MatrixXd N = heldBasis(body, held);
    const Eigen::Index m = body.numModes(), n = N.cols();
    if (n > 0) (void)heldStiffness(body, N);  // throws if the held body can move rigidly
    Eigen::VectorXd& c = damping_;
    c = modalDampingCoefficients(body);
    coupled_ = hasSupportDamping(body);
    dampingMatrix_ = bodyDampingMatrix(body);
    if (n == 0) {  // the held interfaces fix every mode: no response
        inQ_ = inV_ = inF_ = Eigen::MatrixXcd::Zero(0, m);
        outQ_ = outV_ = Eigen::MatrixXcd::Zero(m, 0);
        G_ = Gv_ = Eigen::MatrixXd::Zero(m, m);
        return;
    }
    const Eigen::MatrixXd Mn = N.transpose() * body.massMatrix * N, Kn = N.transpose() * body.stiffnessMatrix * N;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(Kn, Mn);
    if (modes.info() != Eigen::Success)
        throw std::runtime_error("modal propagator: the held body's modes could not be computed");
    const Eigen::MatrixXd& Psi = modes.eigenvectors();  // Ψᵀ Mₙ Ψ = I
    const Eigen::VectorXd omega = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    if (!(omega.minCoeff() > 0.0))
        throw std::runtime_error("modal propagator: the held body has a mode of zero frequency");
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n) = omega.asDiagonal();
    A.bottomLeftCorner(n, n) = -omega.asDiagonal().toDenseMatrix();
    if (coupled_)  // the damper supports couple the modes: the full C = diag(c) + D_s
        A.bottomRightCorner(n, n) = -(Psi.transpose() * N.transpose() * dampingMatrix_ * N * Psi);
    else
        A.bottomRightCorner(n, n) = -(Psi.transpose() * N.transpose() * c.asDiagonal() * N * Psi);
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(A);
    if (eig.info() != Eigen::Success)
        throw std::runtime_error("modal propagator: the damped modes could not be computed");
    lambda_ = eig.eigenvalues();
    const Eigen::MatrixXcd V = eig.eigenvectors();
    const Eigen::MatrixXcd Vinv = V.partialPivLu().inverse();
    // Independent damped modes: V V⁻¹ = I and A V = V Λ to round-off of the largest rate.
    const double scale = std::max(1.0, lambda_.cwiseAbs().maxCoeff());
    const double residual = (A.cast<Complex>() * V - V * lambda_.asDiagonal()).cwiseAbs().maxCoeff() / scale;
    const double inverse = (V * Vinv - Eigen::MatrixXcd::Identity(2 * n, 2 * n)).cwiseAbs().maxCoeff();
    const double condition = V.norm() * Vinv.norm() / double(2 * n);  // ‖V‖‖V⁻¹‖ (Frobenius, scaled)
    if (!(residual < 1e-8) || !(inverse < 1e-8) || !(condition < 1e8))
        throw std::runtime_error("modal propagator: the held body's damped modes are not independent (residual " +
                                 std::to_string(residual) + ", inverse " + std::to_string(inverse) + ", condition " +
                                 std::to_string(condition) + "); is a mode damped (nearly) critically (damping ratio 1)?");
    // x = [Ω u; u̇], u = Ψᵀ Mₙ Nᵀ q;  q = N Ψ Ω⁻¹ x_top, q̇ = N Ψ x_bottom;  B = [0; Ψᵀ Nᵀ].
    const Eigen::MatrixXd toU = Psi.transpose() * Mn * N.transpose();  // n × m
    const Eigen::MatrixXd fromU = N * Psi;                              // m × n
    inQ_ = Vinv.leftCols(n) * (omega.asDiagonal() * toU).cast<Complex>();
    inV_ = Vinv.rightCols(n) * toU.cast<Complex>();
    inF_ = Vinv.rightCols(n) * (Psi.transpose() * N.transpose()).cast<Complex>();
    outQ_ = (fromU * omega.cwiseInverse().asDiagonal()).cast<Complex>() * V.topRows(n);
    outV_ = fromU.cast<Complex>() * V.bottomRows(n);
    G_ = Gv_ = Eigen::MatrixXd::Zero(m, m);
}

Eigen::VectorXcd ModalPropagator::startModes(const Eigen::VectorXd& y, const Eigen::VectorXd& w) const {
    Eigen::VectorXcd z = inQ_ * y.cast<Complex>();
    if (w.size() > 0) z += inV_ * w.cast<Complex>();
    return z;
}

void ModalPropagator::beginStep(const ModalStepStart& start) {
    if (!(start.dt > 0.0)) throw std::invalid_argument("modal propagator: step " + std::to_string(start.dt) + " s must be > 0");
    const Eigen::Index k = lambda_.size();
    const double dt = start.dt;
    Eigen::VectorXcd e(k), w0(k), w1(k);  // e^{λΔt}; weights of fₙ and f₊
    for (Eigen::Index j = 0; j < k; ++j) {
        Complex p1, p2;
        phi(lambda_(j) * dt, p1, p2);
        e(j) = std::exp(lambda_(j) * dt);
        w1(j) = dt * p2;
        w0(j) = dt * p1 - w1(j);
    }
    if (dt != dt_) {
        const Eigen::MatrixXcd weighted = w1.asDiagonal() * inF_;
        G_ = (outQ_ * weighted).real();
        Gv_ = (outV_ * weighted).real();
        dt_ = dt;
    }
    Eigen::VectorXcd z = e.cwiseProduct(startModes(start.y, start.w));
    if (start.f.size() > 0) z += w0.cwiseProduct(inF_ * start.f.cast<Complex>());
    qFree_ = (outQ_ * z).real();
    vFree_ = (outV_ * z).real();
}

void ModalPropagator::respond(const Eigen::VectorXd& f, Eigen::VectorXd& q) const {
    if (dt_ < 0.0) throw std::logic_error("modal propagator: beginStep before respond");
    q.noalias() = G_ * f;
    q += qFree_;
}

void ModalPropagator::loadResponse(const Eigen::VectorXd& f, Eigen::VectorXd& q) const {
    if (dt_ < 0.0) throw std::logic_error("modal propagator: beginStep before loadResponse");
    q.noalias() = G_ * f;
}

Eigen::VectorXd ModalPropagator::velocity(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& f) const {
    return Gv_ * f + vFree_;
}

void ModalPropagator::responseWithin(const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& fStart,
                                     const Eigen::VectorXd& fEnd, double dt, const std::vector<double>& taus,
                                     Eigen::MatrixXd& displacement, Eigen::MatrixXd& velocity) const {
    const Eigen::Index k = lambda_.size();
    const Eigen::VectorXcd z0 = startModes(y, w);
    const Eigen::VectorXcd b0 = inF_ * fStart.cast<Complex>();
    const Eigen::VectorXcd slope = inF_ * ((fEnd - fStart) / dt).cast<Complex>();
    Eigen::MatrixXcd Z(k, Eigen::Index(taus.size()));
    for (std::size_t i = 0; i < taus.size(); ++i) {
        const double tau = taus[i];
        for (Eigen::Index j = 0; j < k; ++j) {
            Complex p1, p2;
            phi(lambda_(j) * tau, p1, p2);
            Z(j, Eigen::Index(i)) = std::exp(lambda_(j) * tau) * z0(j) + tau * p1 * b0(j) + tau * tau * p2 * slope(j);
        }
    }
    displacement = (outQ_ * Z).real();
    velocity = (outV_ * Z).real();
}

double ModalPropagator::workOver(const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& fStart,
                                 const Eigen::VectorXd& fEnd, double dt, const Eigen::VectorXd& yEnd) const {
    const Eigen::Index k = lambda_.size();
    const Eigen::VectorXcd z0 = startModes(y, w);
    const Eigen::VectorXcd b0 = inF_ * fStart.cast<Complex>();
    const Eigen::VectorXd slope = (fEnd - fStart) / dt;
    const Eigen::VectorXcd s0 = inF_ * slope.cast<Complex>();
    Eigen::VectorXcd integral(k);  // ∫₀^Δt z dt
    for (Eigen::Index j = 0; j < k; ++j) {
        Complex p1, p2;
        const Complex x = lambda_(j) * dt;
        phi(x, p1, p2);
        integral(j) = dt * (p1 * z0(j) + dt * p2 * b0(j) + dt * dt * phi3(x) * s0(j));
    }
    const Eigen::VectorXd qIntegral = (outQ_ * integral).real();
    return fEnd.dot(yEnd) - fStart.dot(y) - slope.dot(qIntegral);
}

}  // namespace flexehd::modal
