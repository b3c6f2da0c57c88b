#pragma once
// Drives modal::HeldModalDynamics from rest with BDF2 (BDF1 on the first step) over given step
// sizes, as the co-simulation's step control does (docs/dynamics.md): for the modal integrators'
// tests against closed forms and against the exact ModalPropagator.
#include <vector>

#include <Eigen/Core>

#include "modal/HeldModalDynamics.hpp"

namespace flexehd::test {

/// q at the end of each step of `steps` (s), the force at the step's end from `force(t)`.
template <class Force>
std::vector<Eigen::VectorXd> integrateBdf2(modal::HeldModalDynamics& dyn, const std::vector<double>& steps,
                                           Force force) {
    const Eigen::Index m = dyn.modes();
    Eigen::VectorXd q = Eigen::VectorXd::Zero(m), qOld = q, v = q, vOld = q, qNew;
    std::vector<Eigen::VectorXd> out;
    double t = 0.0, dtOld = 0.0;
    for (const double dt : steps) {
        double a0 = 1.0, a1 = -1.0, a2 = 0.0;
        if (dtOld > 0.0) {
            const double w = dt / dtOld;
            a0 = (1 + 2 * w) / (1 + w), a1 = -(1 + w), a2 = w * w / (1 + w);
        }
        t += dt;
        dyn.setStep(a0, dt);
        const Eigen::VectorXd hq = a1 * q + a2 * qOld, hv = a1 * v + a2 * vOld;
        dyn.respond(force(t), hq, hv, qNew);
        qOld = q, vOld = v;
        q = qNew;
        v = dyn.bdf2Velocity(q, hq);
        dtOld = dt;
        out.push_back(q);
    }
    return out;
}

}  // namespace flexehd::test
