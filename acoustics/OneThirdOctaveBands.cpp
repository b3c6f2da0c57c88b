// OneThirdOctaveBands: IEC 61260-1 base-10 1/3-octave bands, per-bin sums by centre (header).
#include "acoustics/OneThirdOctaveBands.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

double OneThirdOctaveBand::midFrequency_hz(int k) { return 1000.0 * std::pow(10.0, k / 10.0); }
double OneThirdOctaveBand::lowerEdge_hz(int k) { return midFrequency_hz(k) * std::pow(10.0, -1.0 / 20.0); }
double OneThirdOctaveBand::upperEdge_hz(int k) { return midFrequency_hz(k) * std::pow(10.0, 1.0 / 20.0); }

int OneThirdOctaveBand::containing(double frequency_hz) {
    requirePositiveFinite("frequency_hz", frequency_hz, "frequency in Hz");
    int k = static_cast<int>(std::floor(10.0 * std::log10(frequency_hz / 1000.0) + 0.5));
    // The rounding above may land one band off at an edge: settle it on the edges themselves.
    while (frequency_hz < lowerEdge_hz(k)) --k;
    while (frequency_hz >= upperEdge_hz(k)) ++k;
    return k;
}

BandSpectrum sumIntoOneThirdOctaveBands(const Eigen::VectorXd& frequency_hz, const Eigen::VectorXd& value) {
    if (frequency_hz.size() != value.size())
        throw std::invalid_argument("value: expected one value per frequency (" + std::to_string(frequency_hz.size()) +
                                    "), got " + std::to_string(value.size()));
    BandSpectrum out;
    Eigen::Index first = 0;
    while (first < frequency_hz.size() && frequency_hz(first) <= 0.0) ++first;
    if (first == frequency_hz.size()) return out;
    const int lowest = OneThirdOctaveBand::containing(frequency_hz(first));
    const int highest = OneThirdOctaveBand::containing(frequency_hz(frequency_hz.size() - 1));
    const int count = highest - lowest + 1;
    out.band.resize(count);
    out.midFrequency_hz.resize(count);
    out.lowerEdge_hz.resize(count);
    out.upperEdge_hz.resize(count);
    out.value = Eigen::VectorXd::Zero(count);
    for (int i = 0; i < count; ++i) {
        out.band[i] = lowest + i;
        out.midFrequency_hz(i) = OneThirdOctaveBand::midFrequency_hz(lowest + i);
        out.lowerEdge_hz(i) = OneThirdOctaveBand::lowerEdge_hz(lowest + i);
        out.upperEdge_hz(i) = OneThirdOctaveBand::upperEdge_hz(lowest + i);
    }
    for (Eigen::Index b = first; b < frequency_hz.size(); ++b)
        out.value(OneThirdOctaveBand::containing(frequency_hz(b)) - lowest) += value(b);
    return out;
}

}  // namespace flexehd::acoustics
