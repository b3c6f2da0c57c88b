#include "lube/ReynoldsSystem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

void validateFilmState(const FilmGrid& grid, const FilmState& film) {
    const int n = grid.size();
    if (film.h.size() != n)
        throw std::invalid_argument("FilmState: h has " + std::to_string(film.h.size()) +
                                    " values, the grid has " + std::to_string(n) + " nodes");
    if (film.dhdt.size() != 0 && film.dhdt.size() != n)
        throw std::invalid_argument("FilmState: dhdt has " + std::to_string(film.dhdt.size()) +
                                    " values, expected 0 (steady) or " + std::to_string(n));
    for (int k = 0; k < n; ++k) {
        if (grid.kind(k) == NodeKind::Void) continue;
        if (!(film.h[k] > 0.0) || !std::isfinite(film.h[k]))
            throw std::invalid_argument(
                "FilmState: film thickness must be positive and finite, h = " +
                std::to_string(film.h[k]) + " m at node " + std::to_string(k) + " (axial " +
                std::to_string(grid.axialIndex(k)) + ", circumferential " +
                std::to_string(grid.thetaIndex(k)) + ")");
        if (film.dhdt.size() != 0 && !std::isfinite(film.dhdt[k]))
            throw std::invalid_argument("FilmState: dhdt is not finite at node " +
                                        std::to_string(k));
    }
    for (double v : {film.inner.axial, film.inner.circumferential, film.outer.axial,
                     film.outer.circumferential})
        if (!std::isfinite(v))
            throw std::invalid_argument("FilmState: surface velocities must be finite");
}

ReynoldsSystem::ReynoldsSystem(const FilmGrid& grid, const FilmState& film,
                               const Eigen::VectorXd& rho, const Eigen::VectorXd& eta)
    : grid_(&grid) {
    validateFilmState(grid, film);
    const int n = grid.size();
    if (rho.size() != n || eta.size() != n)
        throw std::invalid_argument("ReynoldsSystem: density and viscosity need one value per node");
    for (int k = 0; k < n; ++k)
        if (!(eta[k] > 0.0) || !(rho[k] > 0.0) || !std::isfinite(eta[k]) || !std::isfinite(rho[k]))
            throw std::invalid_argument("ReynoldsSystem: viscosity and density must be positive "
                                        "and finite (node " + std::to_string(k) + ": eta = " +
                                        std::to_string(eta[k]) + ", rho = " +
                                        std::to_string(rho[k]) + ")");

    // Face conductances c_f, stored at the face's lower node: axial face (i,j)–(i+1,j) in cz,
    // circumferential face (i,j)–(i,j+1 mod nθ) in ct; 0 where there is no face.
    b_ = Eigen::VectorXd::Zero(n);
    std::vector<double> cz(static_cast<std::size_t>(n), 0.0), ct(static_cast<std::size_t>(n), 0.0);
    const double Uz = film.sumAxial(), Ut = film.sumCircumferential();
    auto film_ = [&](int k) { return grid.kind(k) == NodeKind::Film; };

    forEachFace(grid, [&](int a, int b, bool axial, double L, double d) {
        const double hf = faceValue(grid, film.h, a, b);
        const double rf = faceValue(grid, rho, a, b);
        const double ef = faceValue(grid, eta, a, b);
        const double c = rf * hf * hf * hf * L / (12.0 * ef * d);
        const double m = 0.5 * (axial ? Uz : Ut) * rf * hf * L;  // Couette flux a → b
        (axial ? cz : ct)[static_cast<std::size_t>(a)] = c;
        if (film_(a)) {
            if (!film_(b)) b_[a] += c * grid.prescribedPressure(b);
            b_[a] -= m;
        }
        if (film_(b)) {
            if (!film_(a)) b_[b] += c * grid.prescribedPressure(a);
            b_[b] += m;
        }
    });
    for (int k = 0; k < n; ++k) {
        if (!film_(k)) b_[k] = grid.prescribedPressure(k);
        else if (film.dhdt.size() != 0) b_[k] -= grid.area(k) * rho[k] * film.dhdt[k];  // squeeze: ∂(ρh)/∂t V_k
    }

    // A in compressed columns, written directly (symmetric: column k = row k). Film node k:
    // diagonal Σ_f c_f over its faces (summed in the face-visiting order of forEachFace), −c_f
    // towards Film neighbours; Fixed/Void nodes: identity.
    const int nz = grid.nAxial(), nt = grid.nTheta();
    const bool periodic = grid.periodic();
    A_.resize(n, n);
    A_.resizeNonZeros(5 * n);
    int* outer = A_.outerIndexPtr();
    int* inner = A_.innerIndexPtr();
    double* val = A_.valuePtr();
    diag_.resize(n);
    int nnz = 0;
    for (int i = 0; i < nz; ++i) {
        for (int j = 0; j < nt; ++j) {
            const int k = i * nt + j;
            outer[k] = nnz;
            if (!film_(k)) {
                inner[nnz] = k;
                val[nnz++] = 1.0;
                diag_[k] = 1.0;
                continue;
            }
            const auto sk = static_cast<std::size_t>(k);
            const bool hasLeft = j > 0 || periodic, hasRight = j + 1 < nt || periodic;
            const int left = j > 0 ? k - 1 : k + nt - 1, right = j + 1 < nt ? k + 1 : k - nt + 1;
            const double cUp = i > 0 ? cz[sk - static_cast<std::size_t>(nt)] : 0.0;
            const double cDown = i + 1 < nz ? cz[sk] : 0.0;
            const double cLeft = hasLeft ? ct[static_cast<std::size_t>(left)] : 0.0;
            const double cRight = hasRight ? ct[sk] : 0.0;
            const double diag = j > 0 ? cUp + cLeft + cDown + cRight : cUp + cDown + cRight + cLeft;
            // Rows in increasing order (the periodic wrap neighbours sit at the far end).
            auto emit = [&](int row, double v) {
                inner[nnz] = row;
                val[nnz++] = v;
            };
            const bool up = i > 0 && film_(k - nt), down = i + 1 < nz && film_(k + nt);
            const bool l = hasLeft && film_(left), r = hasRight && film_(right);
            if (up) emit(k - nt, -cUp);
            if (periodic && j == nt - 1 && r) emit(right, -cRight);
            if (l && left < k) emit(left, -cLeft);
            emit(k, diag);
            if (r && right > k) emit(right, -cRight);
            if (periodic && j == 0 && l) emit(left, -cLeft);
            if (down) emit(k + nt, -cDown);
            diag_[k] = diag;
        }
    }
    outer[n] = nnz;
    A_.resizeNonZeros(nnz);
    for (int k = 0; k < n; ++k)
        if (film_(k) && !(diag_[k] > 0.0))
            throw std::invalid_argument("ReynoldsSystem: film node " + std::to_string(k) +
                                        " has no flow path (isolated by Void nodes?)");
}

double ReynoldsSystem::residual(const Eigen::VectorXd& p, double pLower) const {
    const Eigen::VectorXd w = A_ * p - b_;
    const double pAmb = grid_->ambientPressure();
    double rmax = 0.0, scale = 0.0;
    for (int k = 0; k < p.size(); ++k) {
        scale = std::max(scale, std::abs(p[k] - pAmb));
        if (!isFilm(k)) continue;
        double r = w[k] / diag_[k];
        if (std::isfinite(pLower)) r = std::min(p[k] - pLower, r);
        rmax = std::max(rmax, std::abs(r));
    }
    if (!std::isfinite(rmax) || !std::isfinite(scale))
        return std::numeric_limits<double>::infinity();
    if (rmax == 0.0) return 0.0;
    return rmax / std::max(scale, std::numeric_limits<double>::min());
}

Eigen::VectorXd ReynoldsSystem::initialGuess(double pLower) const {
    Eigen::VectorXd p(grid_->size());
    const double start = std::isfinite(pLower) ? std::max(pLower, grid_->ambientPressure())
                                               : grid_->ambientPressure();
    for (int k = 0; k < p.size(); ++k) p[k] = isFilm(k) ? start : grid_->prescribedPressure(k);
    return p;
}

}  // namespace flexehd::lube
