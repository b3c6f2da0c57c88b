#pragma once
// InputChecks: the argument checks every acoustics entry point shares. Each throws
// std::invalid_argument naming the argument and what was expected, e.g.
// "sampleRate_hz: expected a positive finite rate in Hz, got -1".
#include <Eigen/Core>
#include <string>

namespace flexehd::acoustics {

/// value > 0 and finite; `what` completes "expected a positive finite ..." (e.g. "rate in Hz").
void requirePositiveFinite(const std::string& name, double value, const std::string& what);
/// samples (samples × points): at least 2 rows, at least 1 column, every value finite.
void requireSignalMatrix(const std::string& name, const Eigen::Ref<const Eigen::MatrixXd>& samples);
/// A whole number ≥ lowest.
void requireAtLeast(const std::string& name, long value, long lowest, const std::string& what);

}  // namespace flexehd::acoustics
