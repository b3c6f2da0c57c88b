#pragma once
// EngineOrderSpectrum: a per-bin power (ERP in W, or a mean square) re-expressed over engine
// orders, order = f / f_crank, f_crank = n/60 the crank's rotation frequency at n rpm
// (docs/acoustics.md §5). Order lines sit at m Δo, m = 1, 2, … (Δo = ½ for a four-stroke
// engine, whose cycle is two revolutions); a line holds the bins whose order lies in
// [m Δo − Δo/2, m Δo + Δo/2), each bin wholly in one line (the 0-order line, below Δo/2, is
// not reported). Δo must be at least the bin width in orders, so that no line falls between bins.
#include <Eigen/Core>
#include <vector>

namespace flexehd::acoustics {

struct OrderLine {
    double order;         // m Δo
    double frequency_hz;  // m Δo f_crank
    double power;         // the sum of its bins (the unit of the per-bin values)
};

class EngineOrderSpectrum {
public:
    /// frequency_hz ascending, power ≥ 0 one per bin; crankSpeed_rpm > 0; orderStep Δo > 0.
    EngineOrderSpectrum(const Eigen::VectorXd& frequency_hz, const Eigen::VectorXd& power, double crankSpeed_rpm,
                        double orderStep = 0.5);

    double crankFrequency_hz() const { return crankFrequency_hz_; }
    /// The order of every bin, f_k / f_crank.
    const Eigen::VectorXd& binOrder() const { return binOrder_; }
    /// Every order line from Δo to the highest bin's, ascending.
    const std::vector<OrderLine>& lines() const { return lines_; }
    /// The `count` lines of highest power, highest first (fewer if there are fewer lines).
    std::vector<OrderLine> top(int count) const;

private:
    double crankFrequency_hz_;
    Eigen::VectorXd binOrder_;
    std::vector<OrderLine> lines_;
};

}  // namespace flexehd::acoustics
