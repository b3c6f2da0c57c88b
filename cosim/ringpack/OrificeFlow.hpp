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
    /// dynamic viscosity μ (Pa s): air at 450 K, the lands' default temperature (2.507e-5 Pa s;
    /// Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, Table A.4)
    double viscosity = 2.507e-5;
};

/// r* = (2/(γ+1))^{γ/(γ−1)}.
double criticalPressureRatio(const GasProperties& gas);

/// Mass flow (kg/s) from a to b (negative from b to a) through the orifice cda (C_d A, m²),
/// pressures absolute (Pa, > 0), the upstream side's temperature ta or tb (K). dFlow: when given,
/// ∂ṁ/∂p_a and ∂ṁ/∂p_b (kg/(s Pa)).
double orificeFlow(const GasProperties& gas, double cda, double pa, double pb, double ta, double tb,
                   double* dpa = nullptr, double* dpb = nullptr);

/// Mass flow (kg/s) from a to b through the gap a ring face's oil leaves open (docs/ring-pack.md,
/// "Gas past a face on the oil layer"): laminar, isothermal and compressible across the face,
/// ṁ' = −h_o³ p/(12 μ R T) dp/dx per unit circumference, integrated over the face,
///
///   ṁ = G (p_a² − p_b²)/(24 μ R T),   G = πD / ∫ dx/h_o³  (conductance, m³),
///
/// T the upstream side's temperature; in series with the isentropic flow through the narrowest
/// open height's orifice, limitArea = C_d πD min h_o (m², 0: none), their resistances adding,
/// 1/ṁ = 1/ṁ_channel + 1/ṁ_orifice, so that a wide open gap passes what that orifice does. dpa,
/// dpb as orificeFlow's.
double channelFlow(const GasProperties& gas, double conductance, double limitArea, double pa, double pb, double ta,
                   double tb, double* dpa = nullptr, double* dpb = nullptr);

}  // namespace flexehd::cosim
