#include "cosim/FlexibleSurface.hpp"

#include "cosim/DeformationMapping.hpp"
#include "cosim/LoadMapping.hpp"
#include "modal/ModalSuperposition.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::cosim {

namespace {
std::vector<int> heldIndices(const modal::ReducedBody& body, const std::vector<std::string>& held,
                             const std::string& what) {
    std::vector<int> out;
    std::string names;
    for (std::size_t i = 0; i < body.interfaces.size(); ++i) {
        names += (names.empty() ? "" : ", ") + body.interfaces[i].group;
        if (held.empty() || std::find(held.begin(), held.end(), body.interfaces[i].group) != held.end())
            out.push_back(int(i));
    }
    for (const std::string& h : held) {
        bool found = false;
        for (const auto& itf : body.interfaces) found = found || itf.group == h;
        if (!found)
            throw std::invalid_argument(what + ": interface '" + h + "' is not in the reduced body (it has: " +
                                        (names.empty() ? std::string("none") : names) + ")");
    }
    if (out.empty()) throw std::invalid_argument(what + ": the reduced body has no interface to hold");
    return out;
}
}  // namespace

FlexibleSurface::FlexibleSurface(modal::ReducedBody body, Side side, const std::string& surface,
                                 const std::vector<std::string>& held, const lube::FilmGrid& grid, double zMin, double zMax)
    : body_(std::move(body)), side_(side), surface_(surface) {
    const std::string what = body_.meshPath.empty() ? std::string("reduced body") : body_.meshPath;
    // Compliance with the held reference nodes fixed, C = N (Nᵀ K N)⁻¹ Nᵀ (once).
    held_ = heldIndices(body_, held, what);
    compliance_ = modal::ModalSuperposition(body_).compliance(held_);
    if (side_ == Side::Piston) {
        LoadMapping load(body_.mesh, surface, grid);
        DeformationMapping def(body_.mesh, surface, grid);
        std::vector<int> film;  // the nodes that carry film: the modal products skip the Void ones
        for (int k = 0; k < grid.size(); ++k)
            if (grid.kind(k) != lube::NodeKind::Void) film.push_back(k);
        fixed_ = std::make_unique<ModalMapping>(body_, load, def, std::move(film));
        // Rows summing the mapped nodal forces and their moments about the origin: 6 × grid.
        const Eigen::SparseMatrix<double>& A = load.matrix();  // 3·nodes × grid, column-major
        resultantRows_ = Eigen::MatrixXd::Zero(6, grid.size());
        const Eigen::Matrix3Xd& X = body_.mesh.nodes;
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
    } else {
        const double h = grid.length() / std::max(1, grid.nAxial() - 1);
        const int rows = std::max(3, int(std::ceil((zMax - zMin) / h)) + 1);
        moving_ = std::make_unique<MovingGridMapping>(body_.mesh, surface, grid, zMin, zMax, rows);
        std::vector<int> columns;  // θ columns holding a node that carries film
        for (int j = 0; j < grid.nTheta(); ++j)
            for (int i = 0; i < grid.nAxial(); ++i)
                if (grid.kind(grid.index(i, j)) != lube::NodeKind::Void) {
                    columns.push_back(j);
                    break;
                }
        moving_->setModes(body_.shapes, columns);
        for (int j : columns)
            for (int i = 0; i < grid.nAxial(); ++i)
                if (grid.kind(grid.index(i, j)) == lube::NodeKind::Void) voids_.push_back(grid.index(i, j));
    }
}

void FlexibleSurface::modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const {
    if (fixed_)
        fixed_->modalForce(p, f);
    else
        moving_->modalForce(p, offset, f);
}

void FlexibleSurface::modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const {
    if (fixed_)
        fixed_->modalForces(P, F);
    else
        moving_->modalForces(P, offset, F);
}

void FlexibleSurface::filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const {
    if (fixed_) {
        Psi = -fixed_->gridShapes();  // outward skirt displacement closes the gap
    } else {
        moving_->modalRadialShapes(offset, Psi);
        for (int k : voids_) Psi.row(k).setZero();
    }
}

void FlexibleSurface::respond(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& q) const {
    Eigen::VectorXd f;
    modalForce(p, offset, f);
    quasiStatic(f, q);
}

Eigen::Matrix<double, 6, 1> FlexibleSurface::resultant(const Eigen::VectorXd& p, double offset,
                                                      const Eigen::Vector3d& point) const {
    Eigen::Matrix<double, 6, 1> r;
    if (fixed_) {
        r = resultantRows_ * p;
    } else {
        const Eigen::VectorXd f = moving_->loads(p, offset);
        r.setZero();
        const Eigen::Matrix3Xd& X = body_.mesh.nodes;
        for (Eigen::Index j = 0; j < X.cols(); ++j) {
            const Eigen::Vector3d fj = f.segment<3>(3 * j);
            r.head<3>() += fj;
            r.tail<3>() += X.col(j).cross(fj);
        }
    }
    // Moment about `point`: M_point = M_0 − point × F.
    r.tail<3>() -= point.cross(Eigen::Vector3d(r.head<3>()));
    return r;
}

void FlexibleSurface::filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const {
    if (fixed_) {
        fixed_->radialDisplacement(q, dh);
        dh = -dh;  // outward skirt displacement closes the gap
    } else {
        moving_->modalRadialDisplacement(q, offset, dh);  // outward bore displacement opens it
        for (int k : voids_) dh[k] = 0.0;  // Void nodes of a film column: no film, no elastic Δh
    }
}

}  // namespace flexehd::cosim
