#include "cosim/mapping/FlexibleSurface.hpp"

#include "cosim/mapping/LinerSurfaceMapping.hpp"
#include "cosim/mapping/PistonSurfaceMapping.hpp"
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
    : body_(std::move(body)), surface_(surface) {
    const std::string what = body_.meshPath.empty() ? std::string("reduced body") : body_.meshPath;
    // Compliance with the held reference nodes fixed, C = N (Nᵀ K N)⁻¹ Nᵀ (once).
    held_ = heldIndices(body_, held, what);
    compliance_ = modal::ModalSuperposition(body_).compliance(held_);
    if (side == Side::Piston)
        mapping_ = std::make_unique<PistonSurfaceMapping>(body_, surface, grid);
    else
        mapping_ = std::make_unique<LinerSurfaceMapping>(body_, surface, grid, zMin, zMax);
}

void FlexibleSurface::modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const {
    mapping_->modalForce(p, offset, f);
}

void FlexibleSurface::modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const {
    mapping_->modalForces(P, offset, F);
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
