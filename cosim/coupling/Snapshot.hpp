#pragma once
// Snapshot: the film and the bodies at one written crank angle of a run (the VTK series,
// docs/results-format.md).
#include "cosim/contact/FilmFigures.hpp"

#include <Eigen/Core>

#include <vector>

namespace flexehd::cosim {

/// Film and body state at one written crank angle (the VTK snapshots); the film fields
/// (FilmFields) are the skirt's.
struct Snapshot : FilmFields {
    int cycle = 0;
    double crankDeg = 0.0;       ///< °, the crank angle 0–720 (0 = gas-exchange TDC), as in StepRecord
    double continuousDeg = 0.0;  ///< °, the continuous crank angle: time.start_deg + degrees turned
    double pinHeight = 0.0;      ///< m, cylinder-frame z of the pin axis (crank axis at 0)
    double linerOffset = 0.0;    ///< m, liner-frame z of the piston frame's origin
    double lateral = 0.0, tilt = 0.0;
    /// Mass-conserving film on a liner oil layer (lubricant.supply: liner_layer): the layer outside
    /// the skirt per cell and grid column (m, volume per liner area; cell-major, index c × nθ + j;
    /// empty otherwise) at the liner-frame z of the cells' centres (m).
    Eigen::VectorXd linerOil;
    std::vector<double> linerOilZ;
    Eigen::VectorXd pistonModal, linerModal;  ///< modal coordinates (empty for rigid bodies)
};

}  // namespace flexehd::cosim
