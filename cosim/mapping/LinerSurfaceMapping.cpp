#include "cosim/mapping/LinerSurfaceMapping.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace flexehd::cosim {

LinerSurfaceMapping::LinerSurfaceMapping(const modal::ReducedBody& body, const std::string& surface,
                                         const lube::FilmGrid& grid, double zMin, double zMax)
    : nodes_(body.mesh.nodes) {
    const double h = grid.length() / std::max(1, grid.nAxial() - 1);
    const int rows = std::max(3, int(std::ceil((zMax - zMin) / h)) + 1);
    moving_ = std::make_unique<MovingGridMapping>(body.mesh, surface, grid, zMin, zMax, rows);
    std::vector<int> columns;  // θ columns holding a node that carries film
    for (int j = 0; j < grid.nTheta(); ++j)
        for (int i = 0; i < grid.nAxial(); ++i)
            if (grid.kind(grid.index(i, j)) != lube::NodeKind::Void) {
                columns.push_back(j);
                break;
            }
    moving_->setModes(body.shapes, columns);
    for (int j : columns)
        for (int i = 0; i < grid.nAxial(); ++i)
            if (grid.kind(grid.index(i, j)) == lube::NodeKind::Void) voids_.push_back(grid.index(i, j));
}

void LinerSurfaceMapping::modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const {
    moving_->modalForce(p, offset, f);
}

void LinerSurfaceMapping::modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const {
    moving_->modalForces(P, offset, F);
}

void LinerSurfaceMapping::filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const {
    moving_->modalRadialDisplacement(q, offset, dh);  // outward bore displacement opens the gap
    for (int k : voids_) dh[k] = 0.0;                 // Void nodes of a film column: no film, no elastic Δh
}

void LinerSurfaceMapping::filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const {
    moving_->modalRadialShapes(offset, Psi);
    for (int k : voids_) Psi.row(k).setZero();
}

Eigen::Matrix<double, 6, 1> LinerSurfaceMapping::resultant(const Eigen::VectorXd& p, double offset) const {
    const Eigen::VectorXd f = moving_->loads(p, offset);
    Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
    const Eigen::Matrix3Xd& X = nodes_;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
        const Eigen::Vector3d fj = f.segment<3>(3 * j);
        r.head<3>() += fj;
        r.tail<3>() += X.col(j).cross(fj);
    }
    return r;
}

}  // namespace flexehd::cosim
