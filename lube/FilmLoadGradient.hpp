#pragma once
// FilmLoadGradient: the derivatives of the film's total load on the inner body — force
// (pressure + contact + shear + boundary friction) and its moment about the reference point, as
// integrateFilm computes them (FilmIntegrals.hpp) — with respect to the nodal pressure, film
// thickness and contact pressure, at one film state.
//
// integrateFilm is affine in the pressure and the contact pressure (up to the viscosity's
// pressure dependence) and smooth in h, so a change (δp, δh, δp_c) of many directions at once
// changes the load by Gp δp + Gh δh + Gc δp_c: one pass over the grid instead of one
// integration per direction (the motion rows of the coupled Newton Jacobian, docs/coupling.md §1).
#include <Eigen/Core>

#include "lube/FilmIntegrals.hpp"
#include "lube/NodeColumns.hpp"

namespace flexehd::lube {

struct FilmLoadGradient {
    using Rows = Eigen::Matrix<double, 6, Eigen::Dynamic>;
    /// Rows: F_x, F_y, F_z (N), M_x, M_y, M_z (N·m, about referencePoint); a column per node.
    Rows pressure;          ///< per Pa of the node's pressure
    Rows thickness;         ///< per m of the node's film thickness
    Rows contactPressure;   ///< per Pa of the node's contact pressure

    /// The load change (6 rows) of a set of directions (a column each; empty = none).
    Eigen::MatrixXd change(const Eigen::Ref<const Eigen::MatrixXd>& dp, const Eigen::Ref<const Eigen::MatrixXd>& dh,
                           const Eigen::Ref<const Eigen::MatrixXd>& dpc) const;
    /// change with the pressure and contact pressure changes given on their nodes.
    Eigen::MatrixXd change(const NodeColumns& dp, const Eigen::Ref<const Eigen::MatrixXd>& dh,
                           const NodeColumns& dpc) const;
};

FilmLoadGradient filmLoadGradient(const FilmGrid& grid, const FilmState& film, const Lubricant& lubricant,
                                  const Eigen::VectorXd& pressure, const FilmIntegralOptions& options = {});

}  // namespace flexehd::lube
