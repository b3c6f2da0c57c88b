#pragma once
// The state of the secondary motion and the bodies at an accepted step, the context of the
// next step, and one iterate of it: what the cycle loop (PistonSimulation) and the step
// (StepSolver) pass between them.
#include "cosim/contact/FilmContact.hpp"
#include "cosim/engine/CrankKinematics.hpp"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace flexehd::cosim {

/// The crank angle reduced to 0–720° (the cylinder pressure's abscissa).
inline double crankAngle720(double deg) {
    const double w = std::fmod(deg, 720.0);
    return w < 0.0 ? w + 720.0 : w;
}

/// The piston and bodies at an accepted step.
struct StepState {
    double crankDeg = 0.0;  // continuous
    double time = 0.0;
    double dt = 0.0;        // s, the step that reached this state (0: initial)
    Eigen::Vector2d x = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero();
    Eigen::VectorXd y;      // modal coordinates: the piston's, then the liner's
    Eigen::VectorXd yFrom;  // y of the state the step that reached this one started from (empty: initial)
    bool quadraticModalStart = false;  // y's quadratic extrapolation predicted this step better than the linear one
    // The bodies' quasi-static response to the step's given loads (the flexible piston's crown gas,
    // axial inertia and ring pack, which do not depend on the iterate), and that of the state the
    // step started from (empty: none).
    Eigen::VectorXd yGiven, yGivenFrom;
    Eigen::VectorXd w;      // modal velocities ẏ (bodies.response: dynamic; else empty)
    Eigen::VectorXd f;      // modal forces at y, N (flexible bodies; empty: none yet)
    std::vector<ContactState> films;  // per contact (the squeeze term's history, the warm start)
    LinerOilState oil;                // the liner's oil layer and the contacts' covers on it
};

/// One step from an accepted state: its BDF2 context, crank state and gas force.
struct StepContext {
    ContactStep step;  // dt, the BDF2 coefficients, the piston's velocity, the liner offset
    double crankDeg = 0.0;
    CrankState crank;
    double gas = 0.0;
    const StepState* now = nullptr;
    const StepState* before = nullptr;
};

/// One iterate (e, β, y) of a step.
struct StepEvaluation {
    std::vector<ContactIterate> films;  // per contact
    FilmAction action;                  // the contacts' together
    Eigen::VectorXd Hy;                 // the bodies' response to the contacts' modal loads
    Eigen::VectorXd modalForce;         // the modal loads Hy responds to
    Eigen::Vector2d vel, acc, residual;
    Eigen::Vector2d scale;  // magnitude of the largest terms of each equation (N, N·m)
};

}  // namespace flexehd::cosim
