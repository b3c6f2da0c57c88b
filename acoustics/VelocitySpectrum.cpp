// VelocitySpectrum: one-sided complex amplitudes and power-corrected mean squares (header).
#include "acoustics/VelocitySpectrum.hpp"

namespace flexehd::acoustics {

VelocitySpectrum::VelocitySpectrum(Eigen::MatrixXcd amplitude, int sampleCount, double sampleRate_hz,
                                   WindowKind window, double coherentGain, double powerGain)
    : amplitude_(std::move(amplitude)),
      sampleCount_(sampleCount),
      sampleRate_hz_(sampleRate_hz),
      window_(window),
      amplitudeToPower_(coherentGain * coherentGain / powerGain),
      frequency_hz_(Eigen::VectorXd::LinSpaced(amplitude_.rows(), 0.0,
                                               (amplitude_.rows() - 1) * sampleRate_hz / sampleCount)) {}

double VelocitySpectrum::binFactor(Eigen::Index bin) const {
    const bool nyquist = sampleCount_ % 2 == 0 && bin == sampleCount_ / 2;
    return bin == 0 || nyquist ? 1.0 : 2.0;
}

double VelocitySpectrum::meanSquare(Eigen::Index bin, Eigen::Index point) const {
    return std::norm(amplitude_(bin, point)) * amplitudeToPower_ / binFactor(bin);
}

Eigen::MatrixXd VelocitySpectrum::meanSquare() const {
    Eigen::MatrixXd m(amplitude_.rows(), amplitude_.cols());
    for (Eigen::Index p = 0; p < m.cols(); ++p)
        for (Eigen::Index k = 0; k < m.rows(); ++k) m(k, p) = meanSquare(k, p);
    return m;
}

}  // namespace flexehd::acoustics
