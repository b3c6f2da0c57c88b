#include "lube/ReynoldsSystem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {
constexpr std::size_t sj(int j) { return static_cast<std::size_t>(j); }
}  // namespace


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
    assemble<false>(film, rho.data(), eta.data());
}

ReynoldsSystem::ReynoldsSystem(const FilmGrid& grid, const FilmState& film, double rho, double eta)
    : grid_(&grid) {
    validateFilmState(grid, film);
    if (!(eta > 0.0) || !(rho > 0.0) || !std::isfinite(eta) || !std::isfinite(rho))
        throw std::invalid_argument("ReynoldsSystem: viscosity and density must be positive and "
                                    "finite (eta = " + std::to_string(eta) + ", rho = " +
                                    std::to_string(rho) + ")");
    assemble<true>(film, &rho, &eta);
}

// Row by row: the conductance c_f and Couette flux m_f of every face are computed once — axial
// faces between rows i and i + 1 in a rolling row buffer, circumferential faces of row i in
// another — and written straight into the 5-point stencil of the Film nodes: centre Σ_f c_f,
// −c_f towards Film neighbours, c_f p_nb into b towards Fixed/Void ones. Constant: ρ and η are
// the scalars rho[0], eta[0] (face means of equal values are those values exactly, so the result
// is that of constant vectors).
template <bool Constant>
void ReynoldsSystem::assemble(const FilmState& film, const double* rho, const double* eta) {
    const FilmGrid& grid = *grid_;
    const int n = grid.size();
    const int nz = grid.nAxial(), nt = grid.nTheta();
    const bool periodic = grid.periodic();
    const double R = grid.radius();
    const double Uz = film.sumAxial(), Ut = film.sumCircumferential();
    const NodeKind* kind = grid.kinds();
    const double* pp = grid.prescribedPressures();
    const double* h = film.h.data();
    const bool squeeze = film.dhdt.size() != 0;
    const double* dhdt = squeeze ? film.dhdt.data() : nullptr;
    st_.resize(static_cast<std::size_t>(3) * static_cast<std::size_t>(n));  // every entry written below
    b_.resize(n);
    double* st = st_.data();
    double* bv = b_.data();
    std::vector<double> colL(sj(nt));  // axial face length R·Δθ_j
    std::vector<double> faceD(sj(nt));  // circumferential node (or arc-end) distance R·Δθ_f
    for (int j = 0; j < nt; ++j) {
        colL[sj(j)] = R * grid.angularWidth(j);
        faceD[sj(j)] = R * grid.faceAngle(j);
    }
    std::vector<double> cUp(sj(nt), 0.0), mUp(sj(nt), 0.0), cDn(sj(nt), 0.0), mDn(sj(nt), 0.0),
        cT(sj(nt), 0.0), mT(sj(nt), 0.0);
    auto rhoAt = [&](int k) { return Constant ? rho[0] : rho[k]; };
    // Face a–b: c_f and the Couette mass flux a → b (face values as faceValue()).
    // q (constant ρ, η): ρ L / (12 η d) of the face, so c_f = h_f³ q without a division per face.
    auto face = [&](int a, int b, double U, double L, double d, double q, double& c, double& m) {
        double hf, rf, ef;
        if (kind[a] != NodeKind::Void && kind[b] != NodeKind::Void) {
            hf = 0.5 * (h[a] + h[b]);
            rf = Constant ? rho[0] : 0.5 * (rho[a] + rho[b]);
            ef = Constant ? eta[0] : 0.5 * (eta[a] + eta[b]);
        } else {  // the film ends at this face (faceValue: extrapolated at an arc's cut)
            hf = faceValue(grid, h, a, b);
            rf = Constant ? rho[0] : faceValue(grid, rho, a, b);
            ef = Constant ? eta[0] : faceValue(grid, eta, a, b);
        }
        if constexpr (Constant) c = hf * hf * hf * q;
        else c = rf * hf * hf * hf * L / (12.0 * ef * d);
        m = 0.5 * U * rf * hf * L;
    };
    constexpr NodeKind Film = NodeKind::Film;
    for (int i = 0; i < nz; ++i) {
        const int row = i * nt;
        const bool hasDown = i + 1 < nz;
        const double dz = hasDown ? grid.z(i + 1) - grid.z(i) : 0.0;
        const double Lt = grid.axialWidth(i);
        const double qz = Constant && hasDown ? rho[0] / (12.0 * eta[0] * dz) : 0.0;  // × colL[j]
        const double qt = Constant ? rho[0] * Lt / (12.0 * eta[0]) : 0.0;  // ÷ faceD[j]
        for (int j = 0; j < nt; ++j) {
            const int k = row + j;
            const bool kf = kind[k] == Film;
            cDn[sj(j)] = mDn[sj(j)] = 0.0;
            if (hasDown && (kf || kind[k + nt] == Film))
                face(k, k + nt, Uz, colL[sj(j)], dz, qz * colL[sj(j)], cDn[sj(j)], mDn[sj(j)]);
            cT[sj(j)] = mT[sj(j)] = 0.0;
            if (j + 1 < nt || periodic) {
                const int kr = j + 1 < nt ? k + 1 : row;
                if (kf || kind[kr] == Film) face(k, kr, Ut, Lt, faceD[sj(j)], qt / faceD[sj(j)], cT[sj(j)], mT[sj(j)]);
            }
        }
        for (int j = 0; j < nt; ++j) {
            const int k = row + j;
            double* c = st + 3 * static_cast<std::size_t>(k);
            if (kind[k] != Film) {
                c[kStencilE] = c[kStencilN] = 0.0;
                c[kStencilC] = 1.0;
                bv[k] = pp[k];
                continue;
            }
            const bool hasLeft = j > 0 || periodic, hasRight = j + 1 < nt || periodic;
            const int up = k - nt, down = k + nt;
            const int left = j > 0 ? k - 1 : k + nt - 1, right = j + 1 < nt ? k + 1 : row;
            const std::size_t jl = j > 0 ? sj(j - 1) : sj(nt - 1);
            const double cu = i > 0 ? cUp[sj(j)] : 0.0, cd = hasDown ? cDn[sj(j)] : 0.0;
            const double cl = hasLeft ? cT[jl] : 0.0, cr = hasRight ? cT[sj(j)] : 0.0;
            const bool upFilm = i > 0 && kind[up] == Film, downFilm = hasDown && kind[down] == Film;
            const bool leftFilm = hasLeft && kind[left] == Film, rightFilm = hasRight && kind[right] == Film;
            // Face-visiting order of forEachFace (up, left, down, right; the periodic wrap
            // face of column 0 last), so the sums are those of a face-by-face assembly.
            double bk = 0.0;
            auto inflow = [&](bool exists, bool nbFilm, int nb, double cf, double mf) {  // mf: nb → k
                if (!exists) return;
                if (!nbFilm) bk += cf * pp[nb];
                bk += mf;
            };
            auto outflow = [&](bool exists, bool nbFilm, int nb, double cf, double mf) {  // mf: k → nb
                if (!exists) return;
                if (!nbFilm) bk += cf * pp[nb];
                bk -= mf;
            };
            if (j > 0) {
                inflow(i > 0, upFilm, up, cu, mUp[sj(j)]);
                inflow(true, leftFilm, left, cl, mT[jl]);
                outflow(hasDown, downFilm, down, cd, mDn[sj(j)]);
                outflow(hasRight, rightFilm, right, cr, mT[sj(j)]);
                c[kStencilC] = cu + cl + cd + cr;
            } else {
                inflow(i > 0, upFilm, up, cu, mUp[sj(j)]);
                outflow(hasDown, downFilm, down, cd, mDn[sj(j)]);
                outflow(hasRight, rightFilm, right, cr, mT[sj(j)]);
                inflow(hasLeft, leftFilm, left, cl, mT[jl]);
                c[kStencilC] = cu + cd + cr + cl;
            }
            if (squeeze) bk -= colL[sj(j)] * Lt * rhoAt(k) * dhdt[k];  // squeeze: ∂(ρh)/∂t V_k (area(k))
            bv[k] = bk;
            // Only the east and north couplings are stored: the west one is the west neighbour's
            // east one and the south one the south neighbour's north one (A is symmetric: the
            // same face value, and 0 from both sides when either node is not Film).
            c[kStencilN] = downFilm ? -cd : 0.0;
            c[kStencilE] = rightFilm ? -cr : 0.0;
            if (!(c[kStencilC] > 0.0))
                throw std::invalid_argument("ReynoldsSystem: film node " + std::to_string(k) +
                                            " has no flow path (isolated by Void nodes?)");
        }
        cUp.swap(cDn);
        mUp.swap(mDn);
    }
}

// A in compressed columns from the stencil (symmetric: column k = row k), rows in increasing
// order (the periodic wrap neighbours sit at the far end); Fixed/Void rows are identities.
void ReynoldsSystem::buildMatrix() const {
    const FilmGrid& grid = *grid_;
    const int n = grid.size(), nz = grid.nAxial(), nt = grid.nTheta();
    const bool periodic = grid.periodic();
    A_.resize(n, n);
    A_.resizeNonZeros(5 * n);
    int* outer = A_.outerIndexPtr();
    int* inner = A_.innerIndexPtr();
    double* val = A_.valuePtr();
    diag_.resize(n);
    auto film_ = [&](int k) { return grid.kind(k) == NodeKind::Film; };
    int nnz = 0;
    for (int i = 0; i < nz; ++i) {
        for (int j = 0; j < nt; ++j) {
            const int k = i * nt + j;
            const double* c = &st_[3 * static_cast<std::size_t>(k)];
            outer[k] = nnz;
            diag_[k] = c[kStencilC];
            if (!film_(k)) {
                inner[nnz] = k;
                val[nnz++] = 1.0;
                continue;
            }
            const bool hasLeft = j > 0 || periodic, hasRight = j + 1 < nt || periodic;
            const int left = j > 0 ? k - 1 : k + nt - 1, right = j + 1 < nt ? k + 1 : k - nt + 1;
            auto emit = [&](int row, double v) {
                inner[nnz] = row;
                val[nnz++] = v;
            };
            const bool up = i > 0 && film_(k - nt), down = i + 1 < nz && film_(k + nt);
            const bool l = hasLeft && film_(left), r = hasRight && film_(right);
            const double cS = up ? st_[3 * static_cast<std::size_t>(k - nt) + kStencilN] : 0.0;
            const double cW = l ? st_[3 * static_cast<std::size_t>(left) + kStencilE] : 0.0;
            if (up) emit(k - nt, cS);
            if (periodic && j == nt - 1 && r) emit(right, c[kStencilE]);
            if (l && left < k) emit(left, cW);
            emit(k, c[kStencilC]);
            if (r && right > k) emit(right, c[kStencilE]);
            if (periodic && j == 0 && l) emit(left, cW);
            if (down) emit(k + nt, c[kStencilN]);
        }
    }
    outer[n] = nnz;
    A_.resizeNonZeros(nnz);
    matrixBuilt_ = true;
}

const SparseMatrix& ReynoldsSystem::matrix() const {
    if (!matrixBuilt_) buildMatrix();
    return A_;
}

const Eigen::VectorXd& ReynoldsSystem::diagonal() const {
    if (!matrixBuilt_) buildMatrix();
    return diag_;
}

double ReynoldsSystem::residual(const Eigen::VectorXd& p, double pLower) const {
    const FilmGrid& g = *grid_;
    const int nz = g.nAxial(), nt = g.nTheta();
    const bool periodic = g.periodic();
    const double pAmb = g.ambientPressure();
    const bool bounded = std::isfinite(pLower);
    const double* x = p.data();
    double rmax = 0.0, scale = 0.0;
    for (int i = 0; i < nz; ++i) {
        const double* xm = x + (i > 0 ? i - 1 : 0) * nt;
        const double* x0 = x + i * nt;
        const double* xp = x + (i + 1 < nz ? i + 1 : i) * nt;
        for (int j = 0; j < nt; ++j) {
            const int k = i * nt + j;
            scale = std::max(scale, std::abs(x0[j] - pAmb));
            if (!isFilm(k)) continue;
            // Missing neighbours (open edges) have zero coefficients; clamp their index.
            const int jm = j > 0 ? j - 1 : (periodic ? nt - 1 : 0);
            const int jp = j + 1 < nt ? j + 1 : (periodic ? 0 : nt - 1);
            const double* c = &st_[3 * static_cast<std::size_t>(k)];
            const double cS = i > 0 ? st_[3 * static_cast<std::size_t>(k - nt) + kStencilN] : 0.0;
            const double cW = st_[3 * static_cast<std::size_t>(i * nt + westStencilColumn(j, nt)) + kStencilE];
            const double w = cS * xm[j] + cW * x0[jm] + c[kStencilC] * x0[j] +
                             c[kStencilE] * x0[jp] + c[kStencilN] * xp[j] - b_[k];
            double r = w / c[kStencilC];
            if (bounded) r = std::min(x0[j] - pLower, r);
            rmax = std::max(rmax, std::abs(r));
        }
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
