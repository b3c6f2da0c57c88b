#pragma once
// A reduced body that is a set of independent damped oscillators: unit modal masses, the given
// circular frequencies ω (rad/s) and one damping ratio ζ, identity "shapes" — for the modal
// integrators' tests against closed forms.
#include <cstddef>
#include <numbers>

#include "modal/ReducedBody.hpp"

namespace flexehd::test {

inline modal::ReducedBody oscillatorModes(const Eigen::VectorXd& omega, double zeta) {
    const Eigen::Index m = omega.size();
    modal::ReducedBody b;
    b.shapes = Eigen::MatrixXd::Identity(3 * m, m);
    b.massMatrix = Eigen::MatrixXd::Identity(m, m);
    b.stiffnessMatrix = omega.cwiseAbs2().asDiagonal();
    b.dampingRatios = Eigen::VectorXd::Constant(m, zeta);
    b.frequenciesHz = omega / (2 * std::numbers::pi);
    b.rigidBody.assign(std::size_t(m), 0);
    return b;
}

}  // namespace flexehd::test
