#pragma once
// OneThirdOctaveBands: the base-10 one-third-octave bands of IEC 61260-1:2014 and sums of a
// per-bin quantity over them (docs/acoustics.md §4). Band k (k = 0 is the 1 kHz band) has the
// exact mid frequency f_m = 1000 · 10^(k/10) Hz and edges f_m · 10^(∓1/20); its nominal label
// (…, 800, 1000, 1250, …) is the standard's rounding of f_m and is not used here.
//
// A bin belongs wholly to the band containing its centre frequency, lower edge included, upper
// edge excluded: a bin straddling an edge is not split. The 0 Hz bin belongs to no band.
#include <Eigen/Core>
#include <vector>

namespace flexehd::acoustics {

struct OneThirdOctaveBand {
    static double midFrequency_hz(int k);
    static double lowerEdge_hz(int k);
    static double upperEdge_hz(int k);
    /// The k with lowerEdge_hz(k) ≤ f < upperEdge_hz(k), f > 0 and finite.
    static int containing(double frequency_hz);
};

/// A quantity summed into consecutive bands.
struct BandSpectrum {
    std::vector<int> band;            // k of each row
    Eigen::VectorXd midFrequency_hz;  // exact f_m
    Eigen::VectorXd lowerEdge_hz, upperEdge_hz;
    Eigen::VectorXd value;            // the sum of the bins whose centre lies in the band

    Eigen::Index size() const { return value.size(); }
};

/// value (one per bin at frequency_hz, ascending) summed into every band from the one containing
/// the lowest positive frequency to the one containing the highest (empty bands read 0).
BandSpectrum sumIntoOneThirdOctaveBands(const Eigen::VectorXd& frequency_hz, const Eigen::VectorXd& value);

}  // namespace flexehd::acoustics
