#pragma once
// FlexibleBody: a reduced elastic body as every film contact on it shares it — the reduced body,
// the interfaces held in its quasi-static response and its compliance with them held,
// C = N (Nᵀ K_r N)⁻¹ Nᵀ (ModalSuperposition::quasiStatic, computed once). A FlexibleSurface puts
// it in front of one film grid.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class FlexibleBody {
public:
    /// held: interface groups held in the quasi-static response (empty = all interfaces of the
    /// body). Throws std::invalid_argument naming a group the body does not have.
    FlexibleBody(modal::ReducedBody body, const std::vector<std::string>& held);

    int modes() const { return int(compliance_.rows()); }
    /// Quasi-static modal coordinates q = C f for modal forces f (held interfaces fixed).
    void quasiStatic(const Eigen::VectorXd& f, Eigen::VectorXd& q) const { q.noalias() = compliance_ * f; }
    /// The same for the columns of F (modes × k).
    void quasiStatic(const Eigen::MatrixXd& F, Eigen::MatrixXd& Q) const { Q.noalias() = compliance_ * F; }
    /// Nodal displacement of the whole mesh (3 · nodes, m) for q.
    Eigen::VectorXd displacement(const Eigen::VectorXd& q) const { return body_.shapes * q; }
    const modal::ReducedBody& body() const { return body_; }
    /// Indices (into body().interfaces) of the interfaces held in the response.
    const std::vector<int>& heldInterfaces() const { return held_; }

private:
    modal::ReducedBody body_;
    std::vector<int> held_;
    Eigen::MatrixXd compliance_;
};

}  // namespace flexehd::cosim
