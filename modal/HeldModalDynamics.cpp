#include "modal/HeldModalDynamics.hpp"

#include "modal/ModalDamping.hpp"
#include "modal/ModalSuperposition.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::modal {

HeldModalDynamics::HeldModalDynamics(const ReducedBody& body, const std::vector<int>& held)
    : N_(heldBasis(body, held)), M_(body.massMatrix), C_(bodyDampingMatrix(body)) {  // diag(c) + D_s
    Mn_ = N_.transpose() * M_ * N_;
    Cn_ = N_.transpose() * C_ * N_;
    Kn_ = N_.transpose() * body.stiffnessMatrix * N_;
    if (N_.cols() > 0) (void)heldStiffness(body, N_);  // throws if the held body can move rigidly
}

void HeldModalDynamics::setStep(double a0, double dt) {
    if (!(dt > 0.0) || !(a0 > 0.0))
        throw std::invalid_argument("modal dynamics: step " + std::to_string(dt) + " s, a0 " + std::to_string(a0) +
                                    ": both must be > 0");
    a0_ = a0;
    dt_ = dt;
    const double rate = a0 / dt;
    if (rate == rate_) return;
    llt_.compute(rate * rate * Mn_ + rate * Cn_ + Kn_);  // symmetric positive definite
    if (llt_.info() != Eigen::Success) throw std::runtime_error("modal dynamics: the step matrix is not positive definite");
    rate_ = rate;
}

void HeldModalDynamics::respond(const Eigen::VectorXd& f, const Eigen::VectorXd& hq, const Eigen::VectorXd& hv,
                                Eigen::VectorXd& q) const {
    if (rate_ < 0.0) throw std::logic_error("modal dynamics: setStep before respond");
    const double inv = 1.0 / dt_;
    const Eigen::VectorXd g = f - M_ * (a0_ * inv * inv * hq + inv * hv) - C_ * (inv * hq);
    q.noalias() = N_ * llt_.solve(N_.transpose() * g);
}

void HeldModalDynamics::beginStep(const ModalStepStart& start) {
    setStep(start.a0, start.dt);
    hq_ = start.a1 * start.y;
    hv_ = start.a1 * start.w;
    if (start.a2 != 0.0) {
        hq_ += start.a2 * start.yBefore;
        hv_ += start.a2 * start.wBefore;
    }
}

void HeldModalDynamics::loadResponse(const Eigen::VectorXd& f, Eigen::VectorXd& q) const {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(f.size());
    respond(f, zero, zero, q);
}

}  // namespace flexehd::modal
