#pragma once
// InterRingGas: the gas in the volumes of the ring pack (docs/ring-pack.md, "Gas flow through the
// pack"). A network of volumes joined by orifices, each orifice between two volumes or between a
// volume and the cylinder or the crankcase — a ring's end gap, or one of its groove's flank
// clearances (effective area C_d A, m²; OrificeFlow). The plain pack is a chain:
//
//   cylinder → orifice 0 → volume 0 → orifice 1 → volume 1 → … → volume n−1 → orifice n → crankcase.
//
// Each volume is isothermal at its land temperature: m_i = p_i V_i/(R T_i). A step is backward
// Euler in the volumes' pressures with the cylinder and crankcase pressures of the step's end,
// solved by Newton's method on the network: per volume
//
//   V_i/(R T_i) (p_i − p_i,n)/Δt = Σ ṁ in − Σ ṁ out,
//
// so the gas mass is conserved step by step: what enters from the cylinder is the blow-by into
// the crankcase plus what the volumes gain, to the Newton tolerance. Flow from the cylinder or the
// crankcase is at the temperature of the volume it enters.
#include <Eigen/Core>

#include <vector>

#include "cosim/ringpack/OrificeFlow.hpp"

namespace flexehd::cosim {

/// One orifice of the network: from one end to the other (a volume's index, or kCylinder,
/// kCrankcase), its effective area C_d A (m², ≥ 0); its flow is counted from `from` to `to`.
struct GasOrifice {
    static constexpr int kCylinder = -1, kCrankcase = -2;
    int from = kCylinder, to = kCrankcase;
    double area = 0.0;
    /// In parallel, a ring face's open gap (channelFlow): its conductance G (m³, 0: none) and the
    /// orifice area of its narrowest open height that limits it (m²).
    double channel = 0.0, channelArea = 0.0;
};

class InterRingGas {
public:
    /// The chain: volumes (m³, > 0) and temperatures (K, > 0) per volume; orifices: C_d A (m², ≥ 0),
    /// one more than the volumes; the volumes start at `initialPressure` (Pa, absolute).
    InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                 std::vector<double> orifices, double initialPressure);
    /// A network of the volumes and the orifices between them (each end a volume or the cylinder
    /// or crankcase; every volume reached by at least one orifice).
    InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                 std::vector<GasOrifice> orifices, double initialPressure);

    /// Orifice i's effective area C_d A (m², ≥ 0) from the next step on (a flank clearance that
    /// opens or closes with its ring's axial position).
    void setOrificeArea(int i, double area);
    /// Orifice i's open-gap channel in parallel (GasOrifice::channel, channelArea) from the next
    /// step on (a ring face whose oil leaves the gap open).
    void setChannel(int i, double conductance, double limitArea);

    /// One backward-Euler step of dt (s) to the cylinder and crankcase pressures (Pa, absolute)
    /// at its end. Throws std::runtime_error when Newton's method does not converge.
    void advance(double dt, double cylinderPressure, double crankcasePressure);

    const Eigen::VectorXd& pressures() const { return p_; }  ///< Pa, absolute, per volume
    /// Mass flow (kg/s) through orifice i at the last step's end, from its `from` end to its `to`
    /// end > 0 (in the chain: towards the crankcase).
    double flow(int i) const { return flow_[static_cast<Eigen::Index>(i)]; }
    double blowBy() const;  ///< kg/s into the crankcase, through every orifice that reaches it
    /// The blow-by as a volume flow at normal conditions (DIN 1343: 101 325 Pa, 273.15 K), l/min.
    double blowByLitresPerMinute() const { return litresPerMinute(blowBy(), gas_); }
    /// A mass flow (kg/s) as a volume flow at normal conditions (DIN 1343), l/min.
    static double litresPerMinute(double massFlow, const GasProperties& gas);
    double mass() const;  ///< kg of gas in the volumes

private:
    double endPressure(int end, const Eigen::VectorXd& p) const;
    void flows(const Eigen::VectorXd& p, Eigen::VectorXd& f, Eigen::VectorXd& dFrom, Eigen::VectorXd& dTo) const;

    GasProperties gas_;
    std::vector<double> volume_, temperature_;
    std::vector<GasOrifice> orifice_;
    Eigen::VectorXd p_, flow_;
    double cylinder_ = 0.0, crankcase_ = 0.0;
};

}  // namespace flexehd::cosim
