#include "cosim/mapping/PistonSurfaceMapping.hpp"

#include <Eigen/Geometry>

#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/LoadMapping.hpp"

namespace flexehd::cosim {

PistonSurfaceMapping::PistonSurfaceMapping(const modal::ReducedBody& body, const std::string& surface,
                                           const lube::FilmGrid& grid) {
    LoadMapping load(body.mesh, surface, grid);
    DeformationMapping def(body.mesh, surface, grid);
    std::vector<int> film;  // the nodes that carry film: the modal products skip the Void ones
    for (int k = 0; k < grid.size(); ++k)
        if (grid.kind(k) != lube::NodeKind::Void) film.push_back(k);
    modal_ = std::make_unique<ModalMapping>(body, load, def, std::move(film));
    // Rows summing the mapped nodal forces and their moments about the origin: 6 × grid.
    const Eigen::SparseMatrix<double>& A = load.matrix();  // 3·nodes × grid, column-major
    resultantRows_ = Eigen::MatrixXd::Zero(6, grid.size());
    const Eigen::Matrix3Xd& X = body.mesh.nodes;
    for (int k = 0; k < A.outerSize(); ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) {
            const int dof = int(it.row()), node = dof / 3, c = dof % 3;
            Eigen::Vector3d f = Eigen::Vector3d::Zero();
            f[c] = it.value();
            const Eigen::Vector3d m = X.col(node).cross(f);
            resultantRows_(c, k) += it.value();
            for (int r = 0; r < 3; ++r) resultantRows_(3 + r, k) += m[r];
        }
    for (int k : def.outsideNodes())
        if (grid.kind(k) != lube::NodeKind::Void) outside_.push_back(k);
}

void PistonSurfaceMapping::modalForce(const Eigen::VectorXd& p, double, Eigen::VectorXd& f) const {
    modal_->modalForce(p, f);
}

void PistonSurfaceMapping::modalForces(const Eigen::MatrixXd& P, double, Eigen::MatrixXd& F) const {
    modal_->modalForces(P, F);
}

void PistonSurfaceMapping::modalForces(const lube::NodeColumns& P, int, double, Eigen::MatrixXd& F) const {
    modal_->modalForces(P, F);
}

void PistonSurfaceMapping::filmChange(const Eigen::VectorXd& q, double, Eigen::VectorXd& dh) const {
    modal_->radialDisplacement(q, dh);
    dh = -dh;  // outward skirt displacement closes the gap
}

void PistonSurfaceMapping::filmChangeShapes(double, Eigen::MatrixXd& Psi) const {
    Psi = -modal_->gridShapes();
}

Eigen::Matrix<double, 6, 1> PistonSurfaceMapping::resultant(const Eigen::VectorXd& p, double) const {
    return resultantRows_ * p;
}

}  // namespace flexehd::cosim
