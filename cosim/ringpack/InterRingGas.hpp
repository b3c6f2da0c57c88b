#pragma once
// InterRingGas: the gas in the volumes between the rings (docs/ring-pack.md). A chain
//
//   cylinder → orifice 0 → volume 0 → orifice 1 → volume 1 → … → volume n−1 → orifice n → crankcase,
//
// each orifice a ring's end gap and groove clearances together (effective area C_d A, m²;
// OrificeFlow), each volume isothermal at its land temperature: m_i = p_i V_i/(R T_i). A step
// is backward Euler in the volumes' pressures with the cylinder and crankcase pressures of the
// step's end, solved by Newton's method on the chain (tridiagonal): per volume
//
//   V_i/(R T_i) (p_i − p_i,n)/Δt = ṁ_i − ṁ_{i+1},
//
// so the gas mass is conserved step by step: what enters from the cylinder is the blow-by into
// the crankcase plus what the volumes gain, to the Newton tolerance. Flow from the cylinder is at
// the first volume's temperature.
#include <Eigen/Core>

#include <vector>

#include "cosim/ringpack/OrificeFlow.hpp"

namespace flexehd::cosim {

class InterRingGas {
public:
    /// volumes (m³, > 0) and temperatures (K, > 0) per volume; orifices: C_d A (m², ≥ 0), one
    /// more than the volumes; the volumes start at `initialPressure` (Pa, absolute).
    InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                 std::vector<double> orifices, double initialPressure);

    /// One backward-Euler step of dt (s) to the cylinder and crankcase pressures (Pa, absolute)
    /// at its end. Throws std::runtime_error when Newton's method does not converge.
    void advance(double dt, double cylinderPressure, double crankcasePressure);

    const Eigen::VectorXd& pressures() const { return p_; }  ///< Pa, absolute, per volume
    /// Mass flow (kg/s) through orifice i at the last step's end, towards the crankcase > 0.
    double flow(int i) const { return flow_[static_cast<Eigen::Index>(i)]; }
    double blowBy() const { return flow_[flow_.size() - 1]; }  ///< kg/s into the crankcase
    /// The blow-by as a volume flow at normal conditions (DIN 1343: 101 325 Pa, 273.15 K), l/min.
    double blowByLitresPerMinute() const { return litresPerMinute(blowBy(), gas_); }
    /// A mass flow (kg/s) as a volume flow at normal conditions (DIN 1343), l/min.
    static double litresPerMinute(double massFlow, const GasProperties& gas);
    double mass() const;  ///< kg of gas in the volumes

private:
    void flows(const Eigen::VectorXd& p, Eigen::VectorXd& f, Eigen::VectorXd& dUp, Eigen::VectorXd& dDown) const;

    GasProperties gas_;
    std::vector<double> volume_, temperature_, cda_;
    Eigen::VectorXd p_, flow_;
    double cylinder_ = 0.0, crankcase_ = 0.0;
};

}  // namespace flexehd::cosim
