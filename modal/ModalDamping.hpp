#pragma once
// Modal damping ratios of a reduced body: one ratio for all elastic modes, or ratios per
// frequency band (as measured damping is usually given). Rigid-body modes get none.
#include <string>
#include <vector>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

struct DampingBand {
    double upToHz = 0.0;  ///< the band covers elastic modes with f <= upToHz (above the previous band)
    double ratio = 0.0;   ///< ζ, -
};

/// Parses "FMAX:ZETA" (Hz, -); throws std::invalid_argument naming the text.
DampingBand parseDampingBand(const std::string& text);

/// Sets body.dampingRatios: for each elastic mode the ratio of the first band (in order of
/// upToHz) whose upToHz is >= its frequency, `defaultRatio` above all bands, 0 for
/// rigid-body modes.
void assignModalDamping(ReducedBody& body, double defaultRatio, std::vector<DampingBand> bands);

/// The modal dashpots c_k = 2 ζ_k √K_kk (N·s/m per unit modal coordinate) of the body's ratios.
Eigen::VectorXd modalDampingCoefficients(const ReducedBody& body);

/// Whether the body carries projected damper supports (a non-empty ReducedBody::supportDamping).
inline bool hasSupportDamping(const ReducedBody& body) { return body.supportDamping.size() > 0; }

/// The body's damping matrix in its modal coordinates, C = diag(c_k) + D_s (m x m, N·s/m):
/// modal damping plus the damper supports' projected dashpots, which couple the modes
/// (non-proportional, "non-classical" damping of the projected equations; Craig & Kurdila,
/// *Fundamentals of Structural Dynamics*, 2nd ed., Wiley 2006, on damped MDOF systems).
Eigen::MatrixXd bodyDampingMatrix(const ReducedBody& body);

}  // namespace flexehd::modal
