#pragma once
// LinerFieldTable: a radial displacement field fixed to the liner (bore distortion, liner thermal
// growth), tabulated once on liner-frame rows z_k × the film grid's θ columns and sampled at the
// piston's position every step without rebuilding (like MovingGridMapping; docs/coupling.md §5).
//
// The film grid is fixed to the piston; its node (z_i, θ_j) sits at liner-frame z = z_i + s, with
// s the axial offset (PistonSimulation::linerOffset). Between rows the field is linear in z:
//     u(z, θ_j) = (1 − t) U(k, j) + t U(k + 1, j),  z_k ≤ z ≤ z_{k+1},  t = (z − z_k)/(z_{k+1} − z_k)
// and constant beyond the first and last rows. A call costs O(grid).

#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace flexehd::cosim {

class LinerFieldTable {
public:
    LinerFieldTable() = default;
    /// z: liner-frame rows (m), strictly increasing (one row = a field constant in z); values:
    /// rows × nθ (m), column j at the film grid's θ_j. `name` describes the field in messages.
    /// Throws std::invalid_argument for inconsistent sizes or unordered rows.
    LinerFieldTable(std::vector<double> z, Eigen::MatrixXd values, std::string name);

    /// h += sign · u(z_i + offset, θ_j) at every node of `grid` (θ columns as at construction)
    /// that is not Void.
    void add(const lube::FilmGrid& grid, double offset, double sign, Eigen::VectorXd& h) const;
    /// u at liner-frame z and θ column j (m).
    double at(double z, int j) const;

    const std::vector<double>& rows() const { return z_; }
    const Eigen::MatrixXd& values() const { return values_; }
    const std::string& name() const { return name_; }
    bool empty() const { return z_.empty(); }

private:
    // Row k and weight t of liner-frame z (clamped to the table's ends).
    void locate(double z, int& k, double& t) const;

    std::vector<double> z_;
    Eigen::MatrixXd values_;  // rows × nθ
    std::string name_;
};

}  // namespace flexehd::cosim
