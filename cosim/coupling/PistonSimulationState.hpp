#pragma once
// The private per-step structures of PistonSimulation, shared by its translation units
// (PistonSimulation.cpp: the cycle loop and step control; IterateEvaluation.cpp: one iterate;
// StepIteration.cpp: one step's Newton/coupling iteration; CoupledNewton.cpp: the Jacobian of
// the coupled Newton method).
// Not part of the public interface.
#include "cosim/coupling/PistonSimulation.hpp"
#include "lube/FilmIntegrals.hpp"

#include <vector>

#include <cmath>
#include <limits>

namespace flexehd::cosim {

/// The crank angle reduced to 0–720° (the cylinder pressure's abscissa).
inline double crankAngle720(double deg) {
    const double w = std::fmod(deg, 720.0);
    return w < 0.0 ? w + 720.0 : w;
}

struct PistonSimulation::State {
    double crankDeg = 0.0;  // continuous
    double time = 0.0;
    double dt = 0.0;        // s, the step that reached this state (0: initial)
    Eigen::Vector2d x = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero(), a = Eigen::Vector2d::Zero();
    Eigen::VectorXd y;      // modal coordinates: the piston's, then the liner's
    Eigen::VectorXd w;      // modal velocities ẏ (bodies.response: dynamic; else empty)
    std::vector<ContactState> films;  // per contact (the squeeze term's history, the warm start)
};

struct PistonSimulation::Context {
    ContactStep step;  // dt, the BDF2 coefficients, the piston's velocity, the liner offset
    double crankDeg = 0.0;
    CrankState crank;
    double gas = 0.0;
    const State* now = nullptr;
    const State* before = nullptr;
    Eigen::VectorXd hq, hv;  // dynamic response: BDF2 histories a1 yₙ + a2 yₙ₋₁, a1 ẏₙ + a2 ẏₙ₋₁
};

struct PistonSimulation::Evaluation {
    std::vector<ContactIterate> films;  // per contact
    FilmAction action;                  // the contacts' together
    Eigen::VectorXd Hy;                 // the bodies' response to the contacts' modal loads
    Eigen::Vector2d vel, acc, residual;
    Eigen::Vector2d scale;  // magnitude of the largest terms of each equation (N, N·m)
};

// The modal columns of the coupled Newton method's Jacobian at one linearisation, affine in the
// rate r = a0/Δt (CoupledNewton.cpp): motion rows motionH + r motionRate, modal rows
// I − response(modalH + r modalRate) per body; the rate parts are empty without
// coupling.elastic_squeeze.
struct PistonSimulation::CoupledJacobianParts {
    bool valid = false;
    Eigen::MatrixXd motionH, motionRate;    // 2 × modes
    Eigen::MatrixXd modalH, modalRate;      // modes × modes: the contacts' modal loads (piston rows, liner rows)
    Eigen::VectorXd filmChangePerUnknown;   // 2 + modes: the contacts' largest film change per unit
};

// The step's convergence tolerances (StepIteration.cpp).
struct PistonSimulation::StepTolerances {
    Eigen::Vector2d motion;  // (m, rad): the clearance, and the clearance over the reach
    double reach = 0.0;      // m, the skirt's largest distance from the pin axis
    double forceFloor = 0.0; // N, the reciprocating inertia force m r ω²
    double coupling = 0.0;   // m, coupling.tolerance × clearance
};

// coupling.method newton: the last accepted iterate of the step (its measure, merit, unknowns and
// residual) and the line search's state.
struct PistonSimulation::NewtonIterate {
    double acceptedMeasure = std::numeric_limits<double>::infinity();
    double acceptedMerit = std::numeric_limits<double>::infinity();
    Eigen::Vector2d acceptedX = Eigen::Vector2d::Zero();
    Eigen::VectorXd acceptedY, acceptedF;
    int backtracks = 0;
    bool freshJacobian = false, regularize = false, revisit = false;
};

}  // namespace flexehd::cosim
