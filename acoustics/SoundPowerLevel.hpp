#pragma once
// SoundPowerLevel: a sound power as a level in dB re 1 pW, L_W = 10 log10(P / P_0), P_0 = 1e-12 W
// (docs/acoustics.md §3). Zero power reads −∞ dB.

namespace flexehd::acoustics {

inline constexpr double kReferenceSoundPower_W = 1e-12;

/// L_W of power_W ≥ 0 (finite), dB re 1 pW.
double soundPowerLevel_dB(double power_W);

}  // namespace flexehd::acoustics
