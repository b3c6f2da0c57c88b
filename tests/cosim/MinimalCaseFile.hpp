#pragma once
// The smallest valid case file — the example engine's sizes, rigid bodies, a three-row pressure
// table in p.csv — for the tests of single case keys, which append theirs to it.
namespace flexehd::test {

inline constexpr const char* kMinimalCase = R"(engine:
  bore: 0.086
  stroke: 0.086
  rod_length: 0.1435
  speed_rpm: 1000
  pin_tdc_depth: 0.0335
piston:
  mass: 0.3
  pin_mass: 0.13
  inertia: 2.4e-4
  skirt_top: 0.0108
  skirt_bottom: -0.025
cylinder_pressure: p.csv
)";

inline constexpr const char* kMinimalPressureTable = "crank_angle_deg,pressure_pa\n0,1e5\n360,4e6\n720,1e5\n";

}  // namespace flexehd::test
