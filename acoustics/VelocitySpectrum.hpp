#pragma once
// VelocitySpectrum: the one-sided spectrum of N uniformly sampled real signals, one per surface
// point (docs/acoustics.md §2). Bin k = 0..⌊N/2⌋ sits at f_k = k f_s / N (Hz). It holds the
// amplitude-corrected complex amplitude of every bin and point,
//
//   â_k = c_k X_k / (N CG),   c_k = 1 at 0 Hz and at the Nyquist bin (N even), 2 otherwise,
//
// X_k = Σ w_n x_n e^{−2πikn/N}: a sine of amplitude A (m/s) centred on bin k reads |â_k| = A
// under any window. Between bins the window's scalloping loss lowers it (Hann: 8/(3π), −1.42 dB,
// half a bin off). The power-corrected mean square of a bin,
//
//   m_k = c_k |X_k|² / (N² PG) = |â_k|² CG²/PG / c_k  (m²/s²),
//
// sums over the bins to the record's mean square (Parseval; exact for the rectangular window and
// for tones on bins, unbiased for broadband signals under any window): the quantity to sum over
// bins, bands and orders.
#include <Eigen/Core>
#include <complex>

#include "acoustics/SpectralWindow.hpp"

namespace flexehd::acoustics {

class VelocitySpectrum {
public:
    /// amplitude: bins × points, already amplitude-corrected; sampleCount N of the record.
    VelocitySpectrum(Eigen::MatrixXcd amplitude, int sampleCount, double sampleRate_hz, WindowKind window,
                     double coherentGain, double powerGain);

    Eigen::Index binCount() const { return amplitude_.rows(); }
    Eigen::Index pointCount() const { return amplitude_.cols(); }
    int sampleCount() const { return sampleCount_; }
    double sampleRate_hz() const { return sampleRate_hz_; }
    double binWidth_hz() const { return sampleRate_hz_ / sampleCount_; }
    WindowKind window() const { return window_; }
    /// f_k of every bin (Hz).
    const Eigen::VectorXd& frequency_hz() const { return frequency_hz_; }

    /// â_k per bin and point (m/s for velocities): amplitude-corrected complex amplitudes.
    const Eigen::MatrixXcd& complexAmplitude() const { return amplitude_; }
    /// |â_k| of one bin and point.
    double amplitude(Eigen::Index bin, Eigen::Index point) const { return std::abs(amplitude_(bin, point)); }
    /// m_k of one bin and point: the power-corrected mean square.
    double meanSquare(Eigen::Index bin, Eigen::Index point) const;
    /// m_k of every bin and point (bins × points).
    Eigen::MatrixXd meanSquare() const;

private:
    Eigen::MatrixXcd amplitude_;
    int sampleCount_;
    double sampleRate_hz_;
    WindowKind window_;
    double amplitudeToPower_;  // CG²/PG
    Eigen::VectorXd frequency_hz_;

    double binFactor(Eigen::Index bin) const;  // c_k
};

}  // namespace flexehd::acoustics
