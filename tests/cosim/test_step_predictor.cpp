// The coupled step's start (StepSolver::predictedMotion, docs/coupling.md §1): the second-order
// predictor where the motion's acceleration holds over the steps, the first-order one where the
// last step showed the acceleration reversing (a slap).
#include "cosim/coupling/StepSolver.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace flexehd::cosim;

namespace {

// A state of the motion x(t) = x0 + v0 t + ½ a t² at t, reached by a step dt.
StepState onParabola(const Eigen::Vector2d& x0, const Eigen::Vector2d& v0, const Eigen::Vector2d& a, double t,
                     double dt) {
    StepState s;
    s.time = t;
    s.dt = dt;
    s.x = x0 + v0 * t + 0.5 * a * t * t;
    s.v = v0 + a * t;
    s.a = a;
    return s;
}

}  // namespace

// Constant acceleration: the second-order predictor is the motion itself.
TEST(StepPredictor, AConstantAccelerationIsPredictedExactly) {
    const Eigen::Vector2d x0(1e-6, 2e-4), v0(3e-3, -0.1), a(40.0, 900.0), scale(50e-6, 50e-6 / 0.025);
    const double dt = 1e-4;
    const StepState prev = onParabola(x0, v0, a, dt, dt), s = onParabola(x0, v0, a, 2 * dt, dt);
    const Eigen::Vector2d expected = onParabola(x0, v0, a, 3 * dt, dt).x;
    const Eigen::Vector2d x = StepSolver::predictedMotion(s, prev, dt, scale);
    EXPECT_LE((x - expected).cwiseQuotient(scale).cwiseAbs().maxCoeff(), 1e-12);
}

// The acceleration reversed over the last step (the piston hit the wall: it was accelerating
// towards it, then stopped): the last step was predicted better without the acceleration, so
// the start is the first-order one. Also the first step (no step before it) is second order.
TEST(StepPredictor, AReversedAccelerationDropsTheSecondOrderTerm) {
    const Eigen::Vector2d scale(50e-6, 50e-6 / 0.025);
    const double dt = 1e-4;
    StepState prev;
    prev.dt = dt;
    prev.x = Eigen::Vector2d(40e-6, 0.0);
    prev.v = Eigen::Vector2d(0.2, 0.0);
    prev.a = Eigen::Vector2d(2000.0, 0.0);  // towards the wall
    StepState s = prev;
    s.x = prev.x + dt * prev.v - 0.5 * dt * dt * prev.a;  // stopped by the wall instead
    s.v = Eigen::Vector2d(0.05, 0.0);
    s.a = Eigen::Vector2d(-3000.0, 0.0);
    const Eigen::Vector2d x = StepSolver::predictedMotion(s, prev, dt, scale);
    EXPECT_DOUBLE_EQ(x[0], s.x[0] + dt * s.v[0]);
    EXPECT_DOUBLE_EQ(x[1], s.x[1] + dt * s.v[1]);
    StepState first = prev;
    first.dt = 0.0;  // the initial state
    const Eigen::Vector2d y = StepSolver::predictedMotion(s, first, dt, scale);
    EXPECT_DOUBLE_EQ(y[0], s.x[0] + dt * s.v[0] + 0.5 * dt * dt * s.a[0]);
}

// The modal coordinates on a quadratic y(t) = c0 + c1 t + c2 t², reached by steps of different
// sizes: the quadratic predictor is y itself; with one step of history it is the linear
// extrapolation, on the first step y_n.
TEST(StepPredictor, TheModalCoordinatesFollowTheirQuadraticThroughTheLastThreeStates) {
    Eigen::VectorXd c0(3), c1(3), c2(3);
    c0 << 1e-7, -2e-6, 3e-5;
    c1 << 0.02, 0.5, -4.0;
    c2 << 300.0, -20.0, 1e4;
    auto at = [&](double t) { return Eigen::VectorXd(c0 + t * c1 + t * t * c2); };
    const double t0 = 0.0, t1 = 1.3e-4, t2 = 2.1e-4, dt = 0.6e-4;  // steps 1.3e-4, 0.8e-4, then 0.6e-4
    StepState prev, s;
    prev.time = t1;
    prev.dt = t1 - t0;
    prev.y = at(t1);
    prev.yFrom = at(t0);
    s.time = t2;
    s.dt = t2 - t1;
    s.y = at(t2);
    s.yFrom = prev.y;
    const Eigen::VectorXd expected = at(t2 + dt);
    const Eigen::VectorXd y = StepSolver::predictedModal(s, prev, dt, true);
    EXPECT_LE((y - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    // The linear extrapolation misses the curvature: c2 dt (dt + Δt_n); it is the start where
    // the state before prev is not known.
    const Eigen::VectorXd linear = StepSolver::predictedModal(s, prev, dt, false);
    const Eigen::VectorXd missed = c2 * dt * (dt + s.dt);
    EXPECT_LE((expected - linear - missed).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    prev.yFrom.resize(0);
    EXPECT_LE((StepSolver::predictedModal(s, prev, dt, true) - linear).cwiseAbs().maxCoeff(), 0.0);
    prev.dt = 0.0;  // prev is the initial state
    EXPECT_LE((StepSolver::predictedModal(s, prev, dt, true) - linear).cwiseAbs().maxCoeff(), 0.0);
    s.dt = 0.0;  // s is the initial state
    EXPECT_EQ(StepSolver::predictedModal(s, prev, dt, true), s.y);
}

// The response to the given loads (StepState::yGiven) is extrapolated with y's weights: on a
// quadratic it is exact with three states, linear with two, and unknown (empty) where the state
// before s does not carry it — then the start takes no given-load change.
TEST(StepPredictor, TheGivenLoadsResponseIsExtrapolatedAsTheModalCoordinates) {
    Eigen::VectorXd c0(2), c1(2), c2(2);
    c0 << 4e-6, -1e-6;
    c1 << -0.3, 0.05;
    c2 << 2e3, -700.0;
    auto at = [&](double t) { return Eigen::VectorXd(c0 + t * c1 + t * t * c2); };
    const double t0 = 0.0, t1 = 0.9e-4, t2 = 2.0e-4, dt = 1.4e-4;
    StepState prev, s;
    prev.dt = t1 - t0;
    prev.yGiven = at(t1);
    prev.yGivenFrom = at(t0);
    s.dt = t2 - t1;
    s.yGiven = at(t2);
    const Eigen::VectorXd expected = at(t2 + dt);
    const Eigen::VectorXd q =
        StepSolver::extrapolatedModal(s, prev, dt, true, s.yGiven, prev.yGiven, prev.yGivenFrom);
    EXPECT_LE((q - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    const Eigen::VectorXd linear =
        StepSolver::extrapolatedModal(s, prev, dt, false, s.yGiven, prev.yGiven, prev.yGivenFrom);
    EXPECT_LE((expected - linear - c2 * dt * (dt + s.dt)).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
    EXPECT_EQ(StepSolver::extrapolatedModal(s, prev, dt, true, s.yGiven, prev.yGiven, Eigen::VectorXd()), linear);
    EXPECT_EQ(StepSolver::extrapolatedModal(s, prev, dt, true, s.yGiven, Eigen::VectorXd(), Eigen::VectorXd()).size(), 0);
}
