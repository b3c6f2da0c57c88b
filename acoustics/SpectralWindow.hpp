#pragma once
// SpectralWindow: the taper applied to a record before its DFT, with the gains that undo it
// (docs/acoustics.md §2). The Hann window is the periodic (DFT-even) one,
// w_n = ½ (1 − cos(2πn/N)), n = 0..N−1, whose DFT has exactly three non-zero lines (½, −¼, −¼);
// the rectangular window is w_n = 1.
//
//   coherent gain   CG = (1/N) Σ w_n        amplitude correction 1/CG  (Hann ½)
//   power gain      PG = (1/N) Σ w_n²       power (energy) correction 1/PG  (Hann 3/8)
//   equivalent noise bandwidth ENBW = PG / CG² bins (Hann 1.5)
#include <Eigen/Core>
#include <string>

namespace flexehd::acoustics {

enum class WindowKind { Hann, Rectangular };

class SpectralWindow {
public:
    /// The window of `kind` over `length` samples (length ≥ 2).
    SpectralWindow(WindowKind kind, int length);

    WindowKind kind() const { return kind_; }
    std::string name() const;
    const Eigen::VectorXd& coefficients() const { return w_; }
    double coherentGain() const { return coherentGain_; }
    double powerGain() const { return powerGain_; }
    double equivalentNoiseBandwidth_bins() const { return powerGain_ / (coherentGain_ * coherentGain_); }

private:
    WindowKind kind_;
    Eigen::VectorXd w_;
    double coherentGain_, powerGain_;
};

}  // namespace flexehd::acoustics
