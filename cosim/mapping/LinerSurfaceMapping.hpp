#pragma once
// LinerSurfaceMapping: the SurfaceMapping of a grid that slides along the body (the skirt grid
// along the liner bore): MovingGridMapping with the mode shapes pre-multiplied over the θ
// columns that carry film, σ = +1 (outward bore displacement opens the gap), Δh = 0 on the Void
// nodes of those columns.
#include <memory>
#include <string>
#include <vector>

#include "cosim/mapping/MovingGridMapping.hpp"
#include "cosim/mapping/SurfaceMapping.hpp"
#include "lube/FilmGrid.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class LinerSurfaceMapping final : public SurfaceMapping {
public:
    /// The grid slides over body-frame z in [zMin, zMax] (the grid's own z plus the offset).
    LinerSurfaceMapping(const modal::ReducedBody& body, const std::string& surface, const lube::FilmGrid& grid,
                        double zMin, double zMax);

    void modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const override;
    void modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const override;
    void filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const override;
    void filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const override;
    Eigen::Matrix<double, 6, 1> resultant(const Eigen::VectorXd& p, double offset) const override;

private:
    Eigen::Matrix3Xd nodes_;  // the body mesh nodes (resultant)
    std::unique_ptr<MovingGridMapping> moving_;
    std::vector<int> voids_;  // Void nodes in the columns that carry film (their Δh is set to 0)
};

}  // namespace flexehd::cosim
