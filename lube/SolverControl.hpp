#pragma once
// Settings and report shared by the complementarity solvers (PsorSolver, ActiveSetSolver).
#include <cstdio>
#include <string>

namespace flexehd::lube {

struct SolverControl {
    /// Stop when ReynoldsSystem::residual (relative natural residual) <= tolerance.
    double tolerance = 1e-8;
    /// PSOR sweeps or active-set iterations before giving up (std::runtime_error).
    int maxIterations = 200000;
    /// MultigridSolver only: iterations done even when the start already meets the tolerance
    /// (the nested coarse solves of a cold start, whose prolonged start is not smoothed).
    int minIterations = 0;
};

struct SolveReport {
    int iterations = 0;     ///< PSOR sweeps, or active-set iterations (= factorizations)
    double residual = 0.0;  ///< final relative natural residual
};

/// A residual, tolerance or factor in a solver's message: three significant digits (%g), so that
/// 1e-08 does not read 0.000000.
inline std::string messageNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace flexehd::lube
