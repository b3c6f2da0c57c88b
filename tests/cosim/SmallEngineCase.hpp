#pragma once
// The example engine (examples/engine86, 86 × 86 mm at 1000 rpm) in a small form for the
// co-simulation tests: a synthetic firing pressure trace, rigid bodies, one cycle.
#include "cosim/case/EngineCase.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace flexehd::test {

// A small engine close to the example (86 × 86 mm), with a synthetic firing pressure trace.
inline cosim::EngineCase smallCase() {
    cosim::EngineCase c;
    c.engine = cosim::EngineSpec{};
    c.engine.rodLength = 0.1435;
    c.piston.mass = 0.32;
    c.piston.pinMass = 0.10;
    c.piston.inertia = 2.6e-4;
    c.piston.cgX = 0.0;
    c.piston.cgZ = 0.006;
    c.piston.skirtTop = 0.0108;
    c.piston.skirtBottom = -0.025;
    c.piston.clearance = 50e-6;
    c.piston.skirtHalfAngle = 40.0 * std::numbers::pi / 180.0;
    for (double z = -0.025; z <= 0.01081; z += 0.0358 / 8) {
        const double s = (z - (-0.008)) / 0.018;
        c.piston.profile.push_back({z, 20e-6 * s * s});
    }
    c.lubricant.viscosity = 0.008;
    c.contact.compositeModulus = 5.6e10;
    for (int d = 0; d <= 720; d += 2) {
        const double x = (d - 372.0) / 28.0;
        c.cylinderPressure.push_back({double(d), 1.0e5 + 3.4e6 * std::exp(-x * x)});
    }
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.time.maxCycles = 1;
    return c;
}

// The same with the flexible piston of a reduced-body file (skirt surface, pin bore held) on the
// coarse 12 × 40 grid.
inline cosim::EngineCase smallFlexibleCase(const std::string& pistonFile) {
    cosim::EngineCase c = smallCase();
    c.grid = {12, 40};
    c.pistonBody.model = cosim::BodyModel::Flexible;
    c.pistonBody.file = pistonFile;
    c.pistonBody.surface = "skirt";
    c.pistonBody.interface = "pin_bore";
    c.pistonBody.interfaces = {"pin_bore"};
    return c;
}

/// Steps the outside checks of a run can redo: a tight coupling tolerance (1e-6) and uniform
/// 0.25° steps, every one written as a snapshot.
inline void checkableSteps(cosim::EngineCase& c) {
    c.coupling.tolerance = 1e-6;
    c.coupling.maxIterations = 60;
    c.time.maxStepDeg = 0.25;
    c.output.vtkEveryDeg = 0.25;
}

}  // namespace flexehd::test
