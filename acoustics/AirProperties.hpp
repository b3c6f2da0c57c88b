#pragma once
// AirProperties: the medium a surface radiates into (docs/acoustics.md §3). Defaults: dry air at
// 20 °C and 101.325 kPa, ρ = 1.204 kg/m³, c = 343 m/s.

namespace flexehd::acoustics {

struct AirProperties {
    double density_kg_m3 = 1.204;
    double speedOfSound_m_s = 343.0;

    /// ρc (Pa·s/m = kg/(m²·s)).
    double characteristicImpedance_pa_s_m() const { return density_kg_m3 * speedOfSound_m_s; }
};

}  // namespace flexehd::acoustics
