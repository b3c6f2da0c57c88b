#pragma once
// PistonSurfaceMapping: the SurfaceMapping of a grid fixed to the body (the skirt grid on the
// piston): ModalMapping's pre-multiplied operators over the nodes that carry film, σ = −1
// (outward skirt displacement closes the gap), and the mapped nodal forces' resultant as one
// 6 × grid matrix.
#include <memory>
#include <string>

#include "cosim/mapping/ModalMapping.hpp"
#include "cosim/mapping/SurfaceMapping.hpp"
#include "lube/FilmGrid.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class PistonSurfaceMapping final : public SurfaceMapping {
public:
    /// Throws like LoadMapping and DeformationMapping for the surface.
    PistonSurfaceMapping(const modal::ReducedBody& body, const std::string& surface, const lube::FilmGrid& grid);

    void modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const override;
    void modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const override;
    void modalForces(const lube::NodeColumns& P, int gridSize, double offset, Eigen::MatrixXd& F) const override;
    void filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const override;
    void filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const override;
    Eigen::Matrix<double, 6, 1> resultant(const Eigen::VectorXd& p, double offset) const override;

private:
    std::unique_ptr<ModalMapping> modal_;
    Eigen::MatrixXd resultantRows_;  // 6 × grid: Σ of the mapped nodal forces and moments about 0
};

}  // namespace flexehd::cosim
