// SpectralWindow: Hann or rectangular taper and its gains (header).
#include "acoustics/SpectralWindow.hpp"

#include <cmath>
#include <numbers>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

SpectralWindow::SpectralWindow(WindowKind kind, int length) : kind_(kind), w_(Eigen::VectorXd::Ones(length > 0 ? length : 0)) {
    requireAtLeast("window length", length, 2, "samples");
    if (kind == WindowKind::Hann)
        for (int n = 0; n < length; ++n) w_(n) = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * n / length));
    coherentGain_ = w_.mean();
    powerGain_ = w_.squaredNorm() / length;
}

std::string SpectralWindow::name() const { return kind_ == WindowKind::Hann ? "hann" : "rectangular"; }

}  // namespace flexehd::acoustics
