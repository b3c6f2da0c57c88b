#pragma once
// OrificeFlow: the compressible flow of gas through a ring's end gap or a groove clearance, an
// orifice of effective area C_d A, isentropic from the upstream state (p_u, T_u) to p_d:
//
//   ṁ = C_d A p_u √(2γ/((γ−1) R T_u)) √(r^{2/γ} − r^{(γ+1)/γ}),   r = p_d/p_u,
//
// choked (r held at r*) below r* = (2/(γ+1))^{γ/(γ−1)} (0.528 for air). Near r = 1 the law's
// slope in p_d is unbounded (√(1 − r)); within 1e-4 of r = 1 the flow is taken linear in
// p_u − p_d, continuous with the law there, so that an implicit step's Newton iteration has a
// finite derivative (docs/ring-pack.md).
namespace flexehd::cosim {

struct GasProperties {
    double gamma = 1.4;                 ///< ratio of specific heats (air)
    double gasConstant = 287.0;         ///< specific gas constant R (J/(kg K), air)
};

/// r* = (2/(γ+1))^{γ/(γ−1)}.
double criticalPressureRatio(const GasProperties& gas);

/// Mass flow (kg/s) from a to b (negative from b to a) through the orifice cda (C_d A, m²),
/// pressures absolute (Pa, > 0), the upstream side's temperature ta or tb (K). dFlow: when given,
/// ∂ṁ/∂p_a and ∂ṁ/∂p_b (kg/(s Pa)).
double orificeFlow(const GasProperties& gas, double cda, double pa, double pb, double ta, double tb,
                   double* dpa = nullptr, double* dpb = nullptr);

}  // namespace flexehd::cosim
