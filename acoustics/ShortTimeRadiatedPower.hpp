#pragma once
// ShortTimeRadiatedPower: band ERP over crank angle (docs/acoustics.md §6). Frames of L samples,
// advanced by a hop of H samples, each tapered by the window and analysed by one
// SpectrumAnalyzer (planned once); frame j covers samples [jH, jH + L) and is placed at the crank
// angle of its centre, θ_j = θ_0 + 6 n (jH + L/2) / f_s degrees (n in rpm, θ_0 the first
// sample's angle; not wrapped). Only whole frames: ⌊(N − L)/H⌋ + 1 of them.
#include <Eigen/Core>
#include <vector>

#include "acoustics/RadiatedPower.hpp"
#include "acoustics/SpectralWindow.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"

namespace flexehd::acoustics {

/// Band ERP per frame: power_W(frame, band).
struct CrankAngleBandMap {
    Eigen::VectorXd crankAngle_deg;  // each frame's centre
    std::vector<int> band;           // IEC 61260-1 band index k of each column
    Eigen::VectorXd midFrequency_hz, lowerEdge_hz, upperEdge_hz;
    Eigen::MatrixXd power_W;         // frames × bands
};

class ShortTimeRadiatedPower {
public:
    /// frameLength_samples L ≥ 2, hop_samples H ≥ 1, sampleRate_hz > 0.
    ShortTimeRadiatedPower(RadiatedPower radiatedPower, double sampleRate_hz, int frameLength_samples, int hop_samples,
                           WindowKind window = WindowKind::Hann);

    /// samples: N ≥ L rows × one column per area of the RadiatedPower, finite; the crank at
    /// crankSpeed_rpm > 0, at crankAngleAtFirstSample_deg on row 0.
    CrankAngleBandMap map(const Eigen::MatrixXd& samples, double crankSpeed_rpm, double crankAngleAtFirstSample_deg);

private:
    RadiatedPower radiatedPower_;
    SpectrumAnalyzer analyzer_;
    int hop_;
};

}  // namespace flexehd::acoustics
