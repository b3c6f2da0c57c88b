// SpectrumAnalyzer: FFTW real-to-complex DFT planned once, executed per point (header).
#include "acoustics/SpectrumAnalyzer.hpp"

#include <fftw3.h>

#include <complex>
#include <mutex>
#include <stdexcept>
#include <string>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

namespace {
std::mutex& plannerLock() {
    static std::mutex m;
    return m;
}
}  // namespace

struct SpectrumAnalyzer::Plan {
    int n;
    double sampleRate_hz;
    SpectralWindow window;
    double* in = nullptr;
    fftw_complex* out = nullptr;
    fftw_plan plan = nullptr;

    Plan(int count, double rate, WindowKind kind) : n(count), sampleRate_hz(rate), window(kind, count) {
        std::lock_guard<std::mutex> lock(plannerLock());
        in = fftw_alloc_real(static_cast<size_t>(n));
        out = fftw_alloc_complex(static_cast<size_t>(n / 2 + 1));
        if (in && out) plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
        if (!plan) {
            releaseLocked();
            throw std::runtime_error("SpectrumAnalyzer: FFTW could not plan a DFT of " + std::to_string(n) + " samples");
        }
    }
    ~Plan() {
        std::lock_guard<std::mutex> lock(plannerLock());
        releaseLocked();
    }
    void releaseLocked() {  // with plannerLock() held: fftw_destroy_plan is not thread-safe either
        if (plan) fftw_destroy_plan(plan);
        fftw_free(in);
        fftw_free(out);
        plan = nullptr;
        in = nullptr;
        out = nullptr;
    }
};

SpectrumAnalyzer::SpectrumAnalyzer(int sampleCount, double sampleRate_hz, WindowKind window) {
    requireAtLeast("sampleCount", sampleCount, 2, "samples per record");
    requirePositiveFinite("sampleRate_hz", sampleRate_hz, "rate in Hz");
    plan_ = std::make_unique<Plan>(sampleCount, sampleRate_hz, window);
}

SpectrumAnalyzer::~SpectrumAnalyzer() = default;
SpectrumAnalyzer::SpectrumAnalyzer(SpectrumAnalyzer&&) noexcept = default;
SpectrumAnalyzer& SpectrumAnalyzer::operator=(SpectrumAnalyzer&&) noexcept = default;

int SpectrumAnalyzer::sampleCount() const { return plan_->n; }
double SpectrumAnalyzer::sampleRate_hz() const { return plan_->sampleRate_hz; }
const SpectralWindow& SpectrumAnalyzer::window() const { return plan_->window; }

VelocitySpectrum SpectrumAnalyzer::analyze(const Eigen::Ref<const Eigen::MatrixXd>& samples) {
    requireSignalMatrix("samples", samples);
    const int n = plan_->n;
    if (samples.rows() != n)
        throw std::invalid_argument("samples: expected " + std::to_string(n) +
                                    " rows (the analyser's record length), got " + std::to_string(samples.rows()));
    const Eigen::VectorXd& w = plan_->window.coefficients();
    const double cg = plan_->window.coherentGain();
    const Eigen::Index bins = n / 2 + 1;
    Eigen::MatrixXcd amplitude(bins, samples.cols());
    for (Eigen::Index p = 0; p < samples.cols(); ++p) {
        for (int i = 0; i < n; ++i) plan_->in[i] = w(i) * samples(i, p);
        fftw_execute(plan_->plan);
        for (Eigen::Index k = 0; k < bins; ++k) {
            const bool single = k == 0 || (n % 2 == 0 && k == n / 2);
            const double scale = (single ? 1.0 : 2.0) / (n * cg);
            amplitude(k, p) = scale * std::complex<double>(plan_->out[k][0], plan_->out[k][1]);
        }
    }
    return VelocitySpectrum(std::move(amplitude), n, plan_->sampleRate_hz, plan_->window.kind(), cg,
                            plan_->window.powerGain());
}

}  // namespace flexehd::acoustics
