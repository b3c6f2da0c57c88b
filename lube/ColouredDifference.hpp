#pragma once
// ColouredDifference: the sparse finite-difference derivative ∂w/∂h of a film's balance rows w
// in the nodal film thickness h, one residual evaluation per colour of a distance-2 colouring
// (GridColouring; Curtis, Powell & Reid, J. Inst. Maths Applics 13 (1974) 117). A balance row
// depends on h at its node and the four grid neighbours, and no two nodes of one colour share a
// row: perturbing every non-Void node of colour c by δh_a = 1e-7 h_a (truncation ~1e-7, round-off
// ~1e-9 relative) gives row r's entry for node a of colour c as (w_r(h + δh_c) − w_r(h)) / δh_a.
// The film Jacobians of FilmLinearization (docs/coupling.md §3) and JfoLinearization
// (docs/lube.md §3b) are taken so.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/GridColouring.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube {

/// The residual of the balance rows (one value per row, in the order of rowNodes) at a film state.
using RowResidual = std::function<Eigen::VectorXd(const FilmState&)>;

/// ∂w/∂h (rows × grid nodes, exact zeros left out) at the film state, with w0 the rows' residual
/// there and rowNodes the grid node of each row. Colours without a non-Void node are skipped.
SparseMatrix colouredThicknessDerivative(const FilmGrid& grid, const GridColouring& colouring, const FilmState& film,
                                         const std::vector<int>& rowNodes, const Eigen::VectorXd& w0,
                                         const RowResidual& residual);

}  // namespace flexehd::lube
