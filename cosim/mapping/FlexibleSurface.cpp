#include "cosim/mapping/FlexibleSurface.hpp"

#include "cosim/mapping/LinerSurfaceMapping.hpp"
#include "cosim/mapping/PistonSurfaceMapping.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::cosim {


FlexibleSurface::FlexibleSurface(modal::ReducedBody body, Side side, const std::string& surface,
                                 const std::vector<std::string>& held, const lube::FilmGrid& grid, double zMin, double zMax)
    : FlexibleSurface(std::make_shared<const FlexibleBody>(std::move(body), held), side, surface, grid, zMin, zMax) {}

FlexibleSurface::FlexibleSurface(std::shared_ptr<const FlexibleBody> body, Side side, const std::string& surface,
                                 const lube::FilmGrid& grid, double zMin, double zMax)
    : flexible_(std::move(body)), surface_(surface) {
    if (side == Side::Piston)
        mapping_ = std::make_unique<PistonSurfaceMapping>(flexible_->body(), surface, grid);
    else
        mapping_ = std::make_unique<LinerSurfaceMapping>(flexible_->body(), surface, grid, zMin, zMax);
}

void FlexibleSurface::modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const {
    mapping_->modalForce(p, offset, f);
}

void FlexibleSurface::modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const {
    mapping_->modalForces(P, offset, F);
}

void FlexibleSurface::modalForces(const lube::NodeColumns& P, int gridSize, double offset, Eigen::MatrixXd& F) const {
    mapping_->modalForces(P, gridSize, offset, F);
}

void FlexibleSurface::filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const {
    mapping_->filmChangeShapes(offset, Psi);
}

void FlexibleSurface::filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const {
    mapping_->filmChange(q, offset, dh);
}

void FlexibleSurface::respond(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& q) const {
    Eigen::VectorXd f;
    modalForce(p, offset, f);
    quasiStatic(f, q);
}

Eigen::Matrix<double, 6, 1> FlexibleSurface::resultant(const Eigen::VectorXd& p, double offset,
                                                      const Eigen::Vector3d& point) const {
    Eigen::Matrix<double, 6, 1> r = mapping_->resultant(p, offset);
    // Moment about `point`: M_point = M_0 − point × F.
    r.tail<3>() -= point.cross(Eigen::Vector3d(r.head<3>()));
    return r;
}

}  // namespace flexehd::cosim
