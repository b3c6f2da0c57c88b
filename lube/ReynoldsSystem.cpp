#include "lube/ReynoldsSystem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
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
    // Every node positive and finite (a NaN or infinity makes the sum non-finite): nothing to
    // name. Else the loop finds the first offending non-Void node (Void nodes may hold anything).
    const bool allValid = n > 0 && film.h.minCoeff() > 0.0 && std::isfinite(film.h.sum()) &&
                          (film.dhdt.size() == 0 || std::isfinite(film.dhdt.sum()));
    for (int k = 0; k < n && !allValid; ++k) {
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
namespace {

// The assembly of ReynoldsSystem's stencil and right-hand side, row by row: faceCoefficients of
// row i, then nodeEquations of row i (which needs the faces above, of row i − 1, kept in the
// rolling buffer cUp, mUp).
template <bool Constant>
class StencilAssembly {
public:
    // bFlow: b without the squeeze term (may be null).
    StencilAssembly(const FilmGrid& grid, const FilmState& film, const double* rho, const double* eta, double* st,
                    double* bv, double* bFlow)
        : grid_(grid), nz_(grid.nAxial()), nt_(grid.nTheta()), periodic_(grid.periodic()),
          Uz_(film.sumAxial()), Ut_(film.sumCircumferential()), kind_(grid.kinds()),
          pp_(grid.prescribedPressures()), h_(film.h.data()), squeeze_(film.dhdt.size() != 0),
          dhdt_(squeeze_ ? film.dhdt.data() : nullptr), rho_(rho), eta_(eta), st_(st), bv_(bv), bFlow_(bFlow),
          colL_(sj(nt_)), faceD_(sj(nt_)), cUp_(sj(nt_), 0.0), mUp_(sj(nt_), 0.0), cDn_(sj(nt_), 0.0),
          mDn_(sj(nt_), 0.0), cT_(sj(nt_), 0.0), mT_(sj(nt_), 0.0) {
        const double R = grid.radius();
        for (int j = 0; j < nt_; ++j) {
            colL_[sj(j)] = R * grid.angularWidth(j);   // axial face length R·Δθ_j
            faceD_[sj(j)] = R * grid.faceAngle(j);     // circumferential node (or arc-end) distance R·Δθ_f
        }
    }

    void run() {
        for (int i = 0; i < nz_; ++i) {
            faceCoefficients(i);
            nodeEquations(i);
            cUp_.swap(cDn_);
            mUp_.swap(mDn_);
        }
    }

private:
    static constexpr NodeKind Film = NodeKind::Film;

    // Face a–b: c_f and the Couette mass flux a → b (face values as faceValue()).
    // q (constant ρ, η): ρ L / (12 η d) of the face, so c_f = h_f³ q without a division per face.
    void face(int a, int b, double U, double L, double d, double q, double& c, double& m) const {
        const double* h = h_;
        const double* rho = rho_;
        const double* eta = eta_;
        double hf, rf, ef;
        if (kind_[a] != NodeKind::Void && kind_[b] != NodeKind::Void) {
            hf = 0.5 * (h[a] + h[b]);
            rf = Constant ? rho[0] : 0.5 * (rho[a] + rho[b]);
            ef = Constant ? eta[0] : 0.5 * (eta[a] + eta[b]);
        } else {  // the film ends at this face (faceValue: extrapolated at an arc's cut)
            hf = faceValue(grid_, h, a, b);
            rf = Constant ? rho[0] : faceValue(grid_, rho, a, b);
            ef = Constant ? eta[0] : faceValue(grid_, eta, a, b);
        }
        if constexpr (Constant) c = hf * hf * hf * q;
        else c = rf * hf * hf * hf * L / (12.0 * ef * d);
        m = 0.5 * U * rf * hf * L;
    }

    // The down (axial) and right (circumferential) faces of row i into cDn, mDn, cT, mT.
    void faceCoefficients(int i) {
        const int nt = nt_, row = i * nt;
        const NodeKind* kind = kind_;
        const bool hasDown = i + 1 < nz_;
        const double dz = hasDown ? grid_.z(i + 1) - grid_.z(i) : 0.0;
        const double Lt = grid_.axialWidth(i);
        const double qz = Constant && hasDown ? rho_[0] / (12.0 * eta_[0] * dz) : 0.0;  // × colL[j]
        const double qt = Constant ? rho_[0] * Lt / (12.0 * eta_[0]) : 0.0;  // ÷ faceD[j]
        const double Uz = Uz_, Ut = Ut_;
        double* cDn = cDn_.data();
        double* mDn = mDn_.data();
        double* cT = cT_.data();
        double* mT = mT_.data();
        const double* colL = colL_.data();
        const double* faceD = faceD_.data();
        for (int j = 0; j < nt; ++j) {
            const int k = row + j;
            const bool kf = kind[k] == Film;
            cDn[j] = mDn[j] = 0.0;
            if (hasDown && (kf || kind[k + nt] == Film)) face(k, k + nt, Uz, colL[j], dz, qz * colL[j], cDn[j], mDn[j]);
            cT[j] = mT[j] = 0.0;
            if (j + 1 < nt || periodic_) {
                const int kr = j + 1 < nt ? k + 1 : row;
                if (kf || kind[kr] == Film) face(k, kr, Ut, Lt, faceD[j], qt / faceD[j], cT[j], mT[j]);
            }
        }
    }

    // The stencil and right-hand side of row i's nodes: centre Σ_f c_f, −c_f towards Film
    // neighbours, c_f p_nb into b towards Fixed/Void ones, the Couette fluxes and the squeeze
    // term; identity rows on the non-Film nodes.
    void nodeEquations(int i) {
        const int nt = nt_, row = i * nt;
        const NodeKind* kind = kind_;
        const double* pp = pp_;
        const bool periodic = periodic_, hasDown = i + 1 < nz_;
        const double Lt = grid_.axialWidth(i);
        for (int j = 0; j < nt; ++j) {
            const int k = row + j;
            double* c = st_ + 3 * static_cast<std::size_t>(k);
            if (kind[k] != Film) {
                c[ReynoldsSystem::kStencilE] = c[ReynoldsSystem::kStencilN] = 0.0;
                c[ReynoldsSystem::kStencilC] = 1.0;
                bv_[k] = pp[k];
                if (bFlow_) bFlow_[k] = pp[k];
                continue;
            }
            const bool hasLeft = j > 0 || periodic, hasRight = j + 1 < nt || periodic;
            const int up = k - nt, down = k + nt;
            const int left = j > 0 ? k - 1 : k + nt - 1, right = j + 1 < nt ? k + 1 : row;
            const std::size_t jl = j > 0 ? sj(j - 1) : sj(nt - 1);
            const double cu = i > 0 ? cUp_[sj(j)] : 0.0, cd = hasDown ? cDn_[sj(j)] : 0.0;
            const double cl = hasLeft ? cT_[jl] : 0.0, cr = hasRight ? cT_[sj(j)] : 0.0;
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
                inflow(i > 0, upFilm, up, cu, mUp_[sj(j)]);
                inflow(true, leftFilm, left, cl, mT_[jl]);
                outflow(hasDown, downFilm, down, cd, mDn_[sj(j)]);
                outflow(hasRight, rightFilm, right, cr, mT_[sj(j)]);
                c[ReynoldsSystem::kStencilC] = cu + cl + cd + cr;
            } else {
                inflow(i > 0, upFilm, up, cu, mUp_[sj(j)]);
                outflow(hasDown, downFilm, down, cd, mDn_[sj(j)]);
                outflow(hasRight, rightFilm, right, cr, mT_[sj(j)]);
                inflow(hasLeft, leftFilm, left, cl, mT_[jl]);
                c[ReynoldsSystem::kStencilC] = cu + cd + cr + cl;
            }
            if (bFlow_) bFlow_[k] = bk;
            if (squeeze_) bk -= colL_[sj(j)] * Lt * (Constant ? rho_[0] : rho_[k]) * dhdt_[k];  // ∂(ρh)/∂t V_k
            bv_[k] = bk;
            // Only the east and north couplings are stored: the west one is the west neighbour's
            // east one and the south one the south neighbour's north one (A is symmetric: the
            // same face value, and 0 from both sides when either node is not Film).
            c[ReynoldsSystem::kStencilN] = downFilm ? -cd : 0.0;
            c[ReynoldsSystem::kStencilE] = rightFilm ? -cr : 0.0;
            if (!(c[ReynoldsSystem::kStencilC] > 0.0))
                throw std::invalid_argument("ReynoldsSystem: film node " + std::to_string(k) +
                                            " has no flow path (isolated by Void nodes?)");
        }
    }

    const FilmGrid& grid_;
    const int nz_, nt_;
    const bool periodic_;
    const double Uz_, Ut_;
    const NodeKind* const kind_;
    const double* const pp_;
    const double* const h_;
    const bool squeeze_;
    const double* const dhdt_;
    const double* const rho_;
    const double* const eta_;
    double* const st_;
    double* const bv_;
    double* const bFlow_;
    std::vector<double> colL_, faceD_;
    std::vector<double> cUp_, mUp_, cDn_, mDn_, cT_, mT_;
};

}  // namespace

template <bool Constant>
void ReynoldsSystem::assemble(const FilmState& film, const double* rho, const double* eta) {
    const int n = grid_->size();
    st_.resize(static_cast<std::size_t>(3) * static_cast<std::size_t>(n));  // every entry written below
    b_.resize(n);
    if (Constant) {
        density_ = rho[0];
        flowRhs_.resize(n);
    }
    StencilAssembly<Constant>(*grid_, film, rho, eta, st_.data(), b_.data(), Constant ? flowRhs_.data() : nullptr).run();
}

// b = b_flow − V_k ρ ḣ_k on the Film rows, in the assembly's order of operations (V_k = R Δθ_j Δz_i).
void ReynoldsSystem::setSqueezeRate(const Eigen::VectorXd& dhdt) {
    const FilmGrid& g = *grid_;
    const int n = g.size();
    if (!std::isfinite(density_))
        throw std::logic_error("ReynoldsSystem::setSqueezeRate: only for a system of constant density");
    if (dhdt.size() != n)
        throw std::invalid_argument("ReynoldsSystem::setSqueezeRate: dhdt has " + std::to_string(dhdt.size()) +
                                    " values, the grid " + std::to_string(n) + " nodes");
    for (int k = 0; k < n; ++k) {
        if (g.kind(k) != NodeKind::Film) continue;
        if (!std::isfinite(dhdt[k]))
            throw std::invalid_argument("ReynoldsSystem::setSqueezeRate: dhdt is not finite at node " +
                                        std::to_string(k));
        b_[k] = flowRhs_[k] - g.area(k) * density_ * dhdt[k];
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
            diag_[k] = c[ReynoldsSystem::kStencilC];
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
            if (periodic && j == nt - 1 && r) emit(right, c[ReynoldsSystem::kStencilE]);
            if (l && left < k) emit(left, cW);
            emit(k, c[ReynoldsSystem::kStencilC]);
            if (r && right > k) emit(right, c[ReynoldsSystem::kStencilE]);
            if (periodic && j == 0 && l) emit(left, cW);
            if (down) emit(k + nt, c[ReynoldsSystem::kStencilN]);
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
            const double w = cS * xm[j] + cW * x0[jm] + c[ReynoldsSystem::kStencilC] * x0[j] +
                             c[ReynoldsSystem::kStencilE] * x0[jp] + c[ReynoldsSystem::kStencilN] * xp[j] - b_[k];
            double r = w / c[ReynoldsSystem::kStencilC];
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
