#pragma once
// SpectrumAnalyzer: VelocitySpectrum of records of one length by FFTW's real-to-complex DFT,
// planned once (FFTW_ESTIMATE, on buffers of its own) and executed for every point and every
// record it is given (docs/acoustics.md §2). Planning is serialised behind a lock (FFTW's planner
// is not thread-safe); one analyser must not be used by two threads at once, separate analysers
// may.
#include <Eigen/Core>
#include <memory>

#include "acoustics/SpectralWindow.hpp"
#include "acoustics/VelocitySpectrum.hpp"

namespace flexehd::acoustics {

class SpectrumAnalyzer {
public:
    /// Records of sampleCount ≥ 2 samples at sampleRate_hz > 0, tapered by `window`.
    SpectrumAnalyzer(int sampleCount, double sampleRate_hz, WindowKind window = WindowKind::Hann);
    ~SpectrumAnalyzer();
    SpectrumAnalyzer(SpectrumAnalyzer&&) noexcept;
    SpectrumAnalyzer& operator=(SpectrumAnalyzer&&) noexcept;
    SpectrumAnalyzer(const SpectrumAnalyzer&) = delete;
    SpectrumAnalyzer& operator=(const SpectrumAnalyzer&) = delete;

    int sampleCount() const;
    double sampleRate_hz() const;
    const SpectralWindow& window() const;

    /// The spectrum of samples (sampleCount rows × points, finite; a block of a larger matrix is
    /// taken without a copy).
    VelocitySpectrum analyze(const Eigen::Ref<const Eigen::MatrixXd>& samples);

private:
    struct Plan;
    std::unique_ptr<Plan> plan_;
};

}  // namespace flexehd::acoustics
