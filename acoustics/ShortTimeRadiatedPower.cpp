// ShortTimeRadiatedPower: band ERP of overlapping windowed frames over crank angle (header).
#include "acoustics/ShortTimeRadiatedPower.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

namespace {
// The frame length, checked under its own name before the analyser is planned for it.
int checkedFrameLength(int frameLength_samples, double sampleRate_hz) {
    requireAtLeast("frameLength_samples", frameLength_samples, 2, "samples per frame");
    requirePositiveFinite("sampleRate_hz", sampleRate_hz, "rate in Hz");
    return frameLength_samples;
}
}  // namespace

ShortTimeRadiatedPower::ShortTimeRadiatedPower(RadiatedPower radiatedPower, double sampleRate_hz,
                                               int frameLength_samples, int hop_samples, WindowKind window)
    : radiatedPower_(std::move(radiatedPower)),
      analyzer_(checkedFrameLength(frameLength_samples, sampleRate_hz), sampleRate_hz, window),
      hop_(hop_samples) {
    requireAtLeast("hop_samples", hop_samples, 1, "samples between frame starts");
}

CrankAngleBandMap ShortTimeRadiatedPower::map(const Eigen::MatrixXd& samples, double crankSpeed_rpm,
                                              double crankAngleAtFirstSample_deg) {
    requireSignalMatrix("samples", samples);
    requirePositiveFinite("crankSpeed_rpm", crankSpeed_rpm, "crank speed in rpm");
    if (!std::isfinite(crankAngleAtFirstSample_deg))
        throw std::invalid_argument("crankAngleAtFirstSample_deg: expected a finite angle in degrees, got " +
                                    std::to_string(crankAngleAtFirstSample_deg));
    const int length = analyzer_.sampleCount();
    if (samples.rows() < length)
        throw std::invalid_argument("samples: expected at least one frame (" + std::to_string(length) +
                                    " rows), got " + std::to_string(samples.rows()));
    if (samples.cols() != radiatedPower_.pointArea_m2().size())
        throw std::invalid_argument("pointArea_m2: expected one area per point of samples (" +
                                    std::to_string(samples.cols()) + " columns), got " +
                                    std::to_string(radiatedPower_.pointArea_m2().size()) + " areas");
    const Eigen::Index frames = (samples.rows() - length) / hop_ + 1;
    const double degreesPerSecond = 6.0 * crankSpeed_rpm;
    CrankAngleBandMap out;
    out.crankAngle_deg.resize(frames);
    for (Eigen::Index j = 0; j < frames; ++j) {
        const Eigen::Index start = j * hop_;
        const BandSpectrum bands =
            radiatedPower_.inOneThirdOctaveBands_W(analyzer_.analyze(samples.middleRows(start, length)));
        if (j == 0) {
            out.band = bands.band;
            out.midFrequency_hz = bands.midFrequency_hz;
            out.lowerEdge_hz = bands.lowerEdge_hz;
            out.upperEdge_hz = bands.upperEdge_hz;
            out.power_W.resize(frames, bands.size());
        }
        out.power_W.row(j) = bands.value.transpose();
        out.crankAngle_deg(j) =
            crankAngleAtFirstSample_deg + degreesPerSecond * (start + 0.5 * length) / analyzer_.sampleRate_hz();
    }
    return out;
}

}  // namespace flexehd::acoustics
