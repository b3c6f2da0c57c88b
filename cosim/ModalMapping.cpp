#include "cosim/ModalMapping.hpp"

#include <stdexcept>
#include <string>

namespace flexehd::cosim {

ModalMapping::ModalMapping(const modal::ReducedBody& body, const LoadMapping& load,
                           const DeformationMapping& deformation) {
    const Eigen::MatrixXd& phi = body.shapes;
    const auto& A = load.matrix();
    const auto& D = deformation.radial();
    if (A.rows() != phi.rows() || D.cols() != phi.rows())
        throw std::invalid_argument("ModalMapping: the reduced body has " + std::to_string(phi.rows()) +
                                    " dofs, the load mapping " + std::to_string(A.rows()) +
                                    " and the deformation mapping " + std::to_string(D.cols()) +
                                    ": not the same mesh");
    if (A.cols() != D.rows())
        throw std::invalid_argument("ModalMapping: the load mapping has " + std::to_string(A.cols()) +
                                    " grid nodes, the deformation mapping " + std::to_string(D.rows()) +
                                    ": not the same grid");
    B_ = (A.transpose() * phi).transpose();  // Φᵀ A, via the column-major sparse transpose
    G_ = D * phi;
}

Eigen::VectorXd ModalMapping::modalForce(const Eigen::VectorXd& p) const {
    Eigen::VectorXd out;
    modalForce(p, out);
    return out;
}

void ModalMapping::modalForce(const Eigen::VectorXd& p, Eigen::VectorXd& out) const {
    if (p.size() != B_.cols())
        throw std::invalid_argument("ModalMapping::modalForce: " + std::to_string(p.size()) +
                                    " pressures for a grid of " + std::to_string(B_.cols()) + " nodes");
    out.noalias() = B_ * p;
}

Eigen::VectorXd ModalMapping::radialDisplacement(const Eigen::VectorXd& q) const {
    Eigen::VectorXd out;
    radialDisplacement(q, out);
    return out;
}

void ModalMapping::radialDisplacement(const Eigen::VectorXd& q, Eigen::VectorXd& out) const {
    if (q.size() != G_.cols())
        throw std::invalid_argument("ModalMapping::radialDisplacement: " + std::to_string(q.size()) +
                                    " modal coordinates for " + std::to_string(G_.cols()) + " modes");
    out.noalias() = G_ * q;
}

}  // namespace flexehd::cosim
