#include "cosim/clearance/LinerFieldTable.hpp"

#include <algorithm>
#include <stdexcept>

namespace flexehd::cosim {

LinerFieldTable::LinerFieldTable(std::vector<double> z, Eigen::MatrixXd values, std::string name)
    : z_(std::move(z)), values_(std::move(values)), name_(std::move(name)) {
    if (z_.empty() || Eigen::Index(z_.size()) != values_.rows())
        throw std::invalid_argument(name_ + ": liner field table needs one row of values per axial position");
    for (std::size_t k = 1; k < z_.size(); ++k)
        if (!(z_[k] > z_[k - 1]))
            throw std::invalid_argument(name_ + ": liner field table rows must be strictly increasing in z");
}

void LinerFieldTable::locate(double z, int& k, double& t) const {
    const int n = int(z_.size());
    if (n == 1 || z <= z_.front()) {
        k = 0;
        t = 0.0;
        return;
    }
    if (z >= z_.back()) {
        k = n - 2;
        t = 1.0;
        return;
    }
    k = int(std::upper_bound(z_.begin(), z_.end(), z) - z_.begin()) - 1;
    t = (z - z_[std::size_t(k)]) / (z_[std::size_t(k) + 1] - z_[std::size_t(k)]);
}

double LinerFieldTable::at(double z, int j) const {
    int k = 0;
    double t = 0.0;
    locate(z, k, t);
    if (z_.size() == 1) return values_(0, j);
    return (1.0 - t) * values_(k, j) + t * values_(k + 1, j);
}

void LinerFieldTable::add(const lube::FilmGrid& grid, double offset, double sign, Eigen::VectorXd& h) const {
    if (grid.nTheta() != values_.cols() || h.size() != grid.size())
        throw std::invalid_argument(name_ + ": liner field table and film grid differ in size");
    const int nt = grid.nTheta();
    const bool single = z_.size() == 1;
    for (int i = 0; i < grid.nAxial(); ++i) {
        int k = 0;
        double t = 0.0;
        locate(grid.z(i) + offset, k, t);  // body z = grid z + s
        const int k1 = single ? 0 : k + 1;
        for (int j = 0; j < nt; ++j) {
            const int n = grid.index(i, j);
            if (grid.kind(n) == lube::NodeKind::Void) continue;
            h[n] += sign * ((1.0 - t) * values_(k, j) + t * values_(k1, j));
        }
    }
}

}  // namespace flexehd::cosim
