// InputChecks: shared argument checks of acoustics/ (header).
#include "acoustics/InputChecks.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace flexehd::acoustics {

namespace {
std::string text(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}
}  // namespace

void requirePositiveFinite(const std::string& name, double value, const std::string& what) {
    if (!(std::isfinite(value) && value > 0.0))
        throw std::invalid_argument(name + ": expected a positive finite " + what + ", got " + text(value));
}

void requireAtLeast(const std::string& name, long value, long lowest, const std::string& what) {
    if (value < lowest)
        throw std::invalid_argument(name + ": expected " + what + " (at least " + std::to_string(lowest) +
                                    "), got " + std::to_string(value));
}

void requireSignalMatrix(const std::string& name, const Eigen::Ref<const Eigen::MatrixXd>& samples) {
    requireAtLeast(name + " rows", samples.rows(), 2, "samples per point, one row per sample");
    requireAtLeast(name + " columns", samples.cols(), 1, "points, one column per point");
    for (Eigen::Index p = 0; p < samples.cols(); ++p)
        for (Eigen::Index i = 0; i < samples.rows(); ++i)
            if (!std::isfinite(samples(i, p)))
                throw std::invalid_argument(name + ": expected finite values, got " + text(samples(i, p)) +
                                            " at sample " + std::to_string(i) + " of point " + std::to_string(p));
}

}  // namespace flexehd::acoustics
