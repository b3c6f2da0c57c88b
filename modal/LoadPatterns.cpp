#include "modal/LoadPatterns.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::modal {

Eigen::MatrixXd surfacePressurePatterns(const fem::Mesh& mesh, const std::string& surface, int axialOrder,
                                        int circumferentialOrder, int axialHats) {
    if (axialOrder < 0 || circumferentialOrder < 0 || axialHats < 0 || axialHats == 1)
        throw std::invalid_argument("load patterns: orders must be >= 0 and hats 0 or >= 2");
    const int na = axialHats > 0 ? axialHats : axialOrder + 1;
    const auto nodes = mesh.groupNodes(surface);
    double zmin = 1e300, zmax = -1e300;
    for (auto n : nodes) zmin = std::min(zmin, mesh.nodes(2, n)), zmax = std::max(zmax, mesh.nodes(2, n));
    const double half = 0.5 * (zmax - zmin), mid = 0.5 * (zmax + zmin);
    const int nt = 2 * circumferentialOrder + 1;
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(mesh.numNodes(), na * nt);
    for (auto n : nodes) {
        const double zeta = half > 0.0 ? (mesh.nodes(2, n) - mid) / half : 0.0;
        const double theta = std::atan2(mesh.nodes(1, n), mesh.nodes(0, n));
        // Legendre by Bonnet's recursion: (j+1) P_{j+1} = (2j+1) ζ P_j - j P_{j-1}.
        Eigen::VectorXd leg = Eigen::VectorXd::Zero(na);
        if (axialHats > 0) {  // hats centred at ζ_j = -1 + 2j/(n-1)
            const double s = 0.5 * (zeta + 1.0) * (na - 1);
            const int j = std::min(na - 2, static_cast<int>(s));
            leg(j) = 1.0 - (s - j);
            leg(j + 1) = s - j;
        } else {
            leg(0) = 1.0;
            if (na > 1) leg(1) = zeta;
            for (int j = 1; j + 1 < na; ++j) leg(j + 1) = ((2 * j + 1) * zeta * leg(j) - j * leg(j - 1)) / (j + 1);
        }
        for (int j = 0; j < na; ++j) {
            P(n, j * nt) = leg(j);
            for (int m = 1; m <= circumferentialOrder; ++m) {
                P(n, j * nt + 2 * m - 1) = leg(j) * std::cos(m * theta);
                P(n, j * nt + 2 * m) = leg(j) * std::sin(m * theta);
            }
        }
    }
    return P;
}

}  // namespace flexehd::modal
