#include "cosim/results/CycleMetrics.hpp"

#include <numbers>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::cosim {

CycleMetrics cycleMetrics(const std::vector<StepRecord>& c, const PistonDynamics& dyn, double volume) {
    if (c.size() < 2) throw std::invalid_argument("cycle metrics: need at least two steps");
    CycleMetrics m;
    m.duration = c.back().time - c.front().time;
    m.lateralMin = m.lateralMax = c.front().lateral;
    m.tiltMin = m.tiltMax = c.front().tilt;
    m.minFilm = c.front().minFilm;
    m.minFilmDeg = c.front().crankDeg;
    long iterations = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const StepRecord& r = c[i];
        if (i > 0) {
            const double dt = r.time - c[i - 1].time;
            m.frictionEnergy += 0.5 * (r.dissipatedPower + c[i - 1].dissipatedPower) * dt;
            m.boundaryFrictionEnergy += 0.5 * (r.boundaryFrictionPower + c[i - 1].boundaryFrictionPower) * dt;
        }
        const double ke = dyn.kineticEnergy(r.lateralVelocity, r.tiltRate);
        if (ke > m.slapEnergyMax) {
            m.slapEnergyMax = ke;
            m.slapEnergyDeg = r.crankDeg;
        }
        m.lateralMin = std::min(m.lateralMin, r.lateral);
        m.lateralMax = std::max(m.lateralMax, r.lateral);
        m.tiltMin = std::min(m.tiltMin, r.tilt);
        m.tiltMax = std::max(m.tiltMax, r.tilt);
        if (r.minFilm < m.minFilm) {
            m.minFilm = r.minFilm;
            m.minFilmDeg = r.crankDeg;
        }
        m.maxPressure = std::max(m.maxPressure, r.maxPressure);
        if (r.minFilmNodesCircumferential > 0 &&
            (m.minFilmNodesCircumferential == 0 || r.minFilmNodesCircumferential < m.minFilmNodesCircumferential)) {
            m.minFilmNodesCircumferential = r.minFilmNodesCircumferential;
            m.minFilmNodesCircumferentialDeg = r.crankDeg;
        }
        if (r.minFilmNodesAxial > 0 && !r.minFilmAtAxialEdge &&
            (m.minFilmNodesAxial == 0 || r.minFilmNodesAxial < m.minFilmNodesAxial)) {
            m.minFilmNodesAxial = r.minFilmNodesAxial;
            m.minFilmNodesAxialDeg = r.crankDeg;
        }
        m.contactForceMax = std::max(m.contactForceMax, std::abs(r.contactForce));
        m.hardContactForceMax = std::max(m.hardContactForceMax, std::abs(r.hardContactForce));
        m.sideForceMax = std::max(m.sideForceMax, std::abs(r.sideForce));
        iterations += r.couplingIterations;
        m.maxIterations = std::max(m.maxIterations, r.couplingIterations);
    }
    m.frictionPowerMean = m.duration > 0.0 ? m.frictionEnergy / m.duration : 0.0;
    m.boundaryFrictionPowerMean = m.duration > 0.0 ? m.boundaryFrictionEnergy / m.duration : 0.0;
    m.fmep = m.frictionEnergy / volume;
    m.meanIterations = double(iterations) / double(c.size());
    return m;
}

double sweptVolume(const EngineSpec& engine) {
    return 0.25 * std::numbers::pi * engine.bore * engine.bore * engine.stroke;
}

}  // namespace flexehd::cosim
