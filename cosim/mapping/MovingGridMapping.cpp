#include "cosim/mapping/MovingGridMapping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

namespace flexehd::cosim {
namespace {

constexpr int kWindowPad = 30;  // rows beyond the overlap: M⁻¹ decays as (2 − √3)^30 ≈ 7e-18

lube::FilmGrid fixedGridFor(const lube::FilmGrid& g, double zMin, double zMax, int rows) {
    if (rows < 3 || !(zMax > zMin))
        throw std::invalid_argument("MovingGridMapping: the fixed grid needs zMax > zMin and at least 3 rows");
    const auto z = lube::FilmGrid::uniform(zMin, zMax, rows);
    return g.periodic() ? lube::FilmGrid::fullCircumference(g.radius(), z, g.nTheta(), g.theta(0))
                        : lube::FilmGrid::arc(g.radius(), z, g.theta(0), g.theta(g.nTheta() - 1), g.nTheta());
}

}  // namespace

MovingGridMapping::MovingGridMapping(const fem::Mesh& mesh, const std::string& surface,
                                     const lube::FilmGrid& grid, double zMin, double zMax, int fixedRows,
                                     double radiusTolerance)
    : MovingGridMapping(mesh, surface, grid, zMin, zMax, fixedRows, MovingGridOptions{radiusTolerance, false}) {}

MovingGridMapping::MovingGridMapping(const fem::Mesh& mesh, const std::string& surface,
                                     const lube::FilmGrid& grid, double zMin, double zMax, int fixedRows,
                                     const MovingGridOptions& options)
    : z_(grid.axial()),
      nTheta_(grid.nTheta()),
      h_((zMax - zMin) / (fixedRows - 1)),
      fixed_(fixedGridFor(grid, zMin, zMax, fixedRows)),
      load_(mesh, surface, fixed_, {0.0, options.radiusTolerance, options.shear}),
      def_(mesh, surface, fixed_, 0.0, options.radiusTolerance) {}

void MovingGridMapping::checkOffset(double offset) const {
    const double lo = z_.front() + offset, hi = z_.back() + offset;
    const double zMin = fixed_.axial().front(), zMax = fixed_.axial().back(), tol = 1e-12 * (zMax - zMin);
    if (lo < zMin - tol || hi > zMax + tol) {
        std::ostringstream m;
        m.precision(5);
        m << "MovingGridMapping: the grid at offset " << offset * 1e3 << " mm spans z = " << lo * 1e3 << " to "
          << hi * 1e3 << " mm, outside the fixed grid (" << zMin * 1e3 << " to " << zMax * 1e3 << " mm)";
        throw std::out_of_range(m.str());
    }
}

MovingGridMapping::Window MovingGridMapping::transfer(double offset, Transfer& T) const {
    const int nz = static_cast<int>(z_.size()), nZ = fixed_.nAxial();
    checkOffset(offset);
    const double Z0 = fixed_.axial().front(), h = h_;
    auto cellOf = [&](double x) { return std::clamp(static_cast<int>(std::floor((x - Z0) / h)), 0, nZ - 2); };
    const double a0 = z_.front() + offset, a1 = z_.back() + offset;
    Window w;
    w.k0 = std::max(0, cellOf(a0) - kWindowPad);
    const int k1 = std::min(nZ - 1, cellOf(a1) + 1 + kWindowPad);
    w.rows = k1 - w.k0 + 1;

    // T(k, i) = ∫ ψ_k φ_i dz over the merged breakpoints (both linear: Simpson exact).
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(static_cast<std::size_t>(8 * (nz + w.rows)));
    for (int i = 0; i + 1 < nz; ++i) {
        const double x0 = z_[static_cast<std::size_t>(i)] + offset, x1 = z_[static_cast<std::size_t>(i + 1)] + offset;
        for (int k = cellOf(x0); k <= cellOf(x1); ++k) {
            const double Zk = Z0 + k * h;
            const double lo = std::max(x0, Zk), hi = std::min(x1, Zk + h);
            if (!(hi > lo)) continue;
            const std::array<double, 3> x = {lo, 0.5 * (lo + hi), hi}, wt = {1.0, 4.0, 1.0};
            double t[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  // t[a][b] = ∫ ψ_{k+a} φ_{i+b}
            for (int q = 0; q < 3; ++q) {
                const double phi1 = (x[q] - x0) / (x1 - x0), psi1 = (x[q] - Zk) / h;
                const double phi[2] = {1.0 - phi1, phi1}, psi[2] = {1.0 - psi1, psi1};
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b) t[a][b] += wt[q] * (hi - lo) / 6.0 * psi[a] * phi[b];
            }
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) trip.emplace_back(k + a - w.k0, i + b, t[a][b]);
        }
    }
    T.resize(w.rows, nz);
    T.setFromTriplets(trip.begin(), trip.end());
    return w;
}

void MovingGridMapping::solve(const Window& w, const Transfer& T, const Eigen::VectorXd& f, const char* what,
                              Eigen::VectorXd& c) const {
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nZ = fixed_.nAxial();
    if (f.size() != static_cast<Eigen::Index>(nz) * nt)
        throw std::invalid_argument("MovingGridMapping: " + std::to_string(f.size()) + " " + what +
                                    " for a grid of " + std::to_string(nz * nt) + " nodes");
    using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    c.resize(static_cast<Eigen::Index>(w.rows) * nt);
    Eigen::Map<RowMat> B(c.data(), w.rows, nt);
    B.noalias() = T * Eigen::Map<const RowMat>(f.data(), nz, nt);

    // Thomas algorithm on the hats' Gram matrix: off-diagonal h/6, diagonal 2h/3 (h/3 at the
    // ends of G; a window end inside G keeps 2h/3: projection onto the window's hats).
    const double h = h_, off = h / 6.0;
    std::vector<double> diag(static_cast<std::size_t>(w.rows));
    for (int r = 0; r < w.rows; ++r) {
        const int k = w.k0 + r;
        diag[static_cast<std::size_t>(r)] = (k == 0 || k == nZ - 1) ? h / 3.0 : 2.0 * h / 3.0;
    }
    for (int r = 1; r < w.rows; ++r) {
        const double m = off / diag[static_cast<std::size_t>(r - 1)];
        diag[static_cast<std::size_t>(r)] -= m * off;
        B.row(r) -= m * B.row(r - 1);
    }
    B.row(w.rows - 1) /= diag[static_cast<std::size_t>(w.rows - 1)];
    for (int r = w.rows - 2; r >= 0; --r)
        B.row(r) = (B.row(r) - off * B.row(r + 1)) / diag[static_cast<std::size_t>(r)];
}

void MovingGridMapping::requirePressures(Eigen::Index count) const {
    const Eigen::Index n = static_cast<Eigen::Index>(z_.size()) * nTheta_;
    if (count != n)
        throw std::invalid_argument("MovingGridMapping: " + std::to_string(count) + " pressures for a grid of " +
                                    std::to_string(n) + " nodes");
}

MovingGridMapping::Window MovingGridMapping::project(const Eigen::VectorXd& p, double offset,
                                                     Eigen::VectorXd& c) const {
    requirePressures(p.size());  // before the offset check
    Transfer T;
    const Window w = transfer(offset, T);
    solve(w, T, p, "pressures", c);
    return w;
}

template <typename Op>
void MovingGridMapping::applyShear(const Op& opZ, const Op& opTheta, const Eigen::VectorXd& tauZ,
                                   const Eigen::VectorXd& tauTheta, double offset, Eigen::VectorXd& out) const {
    const Eigen::Index n = static_cast<Eigen::Index>(z_.size()) * nTheta_;
    for (const Eigen::VectorXd* t : {&tauZ, &tauTheta})
        if (t->size() != 0 && t->size() != n)
            throw std::invalid_argument("MovingGridMapping: " + std::to_string(t->size()) +
                                        " tractions for a grid of " + std::to_string(n) + " nodes");
    Transfer T;
    const Window w = transfer(offset, T);
    out.setZero(opZ.rows());
    Eigen::VectorXd c;
    const Eigen::Index first = static_cast<Eigen::Index>(w.k0) * nTheta_;
    if (tauZ.size() != 0) {
        solve(w, T, tauZ, "tractions", c);
        out.noalias() += opZ.middleCols(first, c.size()) * c;
    }
    if (tauTheta.size() != 0) {
        solve(w, T, tauTheta, "tractions", c);
        out.noalias() += opTheta.middleCols(first, c.size()) * c;
    }
}

Eigen::VectorXd MovingGridMapping::shearLoads(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta,
                                              double offset) const {
    Eigen::VectorXd f;
    shearLoads(tauZ, tauTheta, offset, f);
    return f;
}

void MovingGridMapping::shearLoads(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta, double offset,
                                   Eigen::VectorXd& forces) const {
    if (!hasShear())
        throw std::logic_error("MovingGridMapping::shearLoads: built without the shear operators (options.shear)");
    applyShear(load_.axialShear(), load_.circumferentialShear(), tauZ, tauTheta, offset, forces);
}

Eigen::VectorXd MovingGridMapping::modalShearForce(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta,
                                                   double offset) const {
    if (!hasShear())
        throw std::logic_error(
            "MovingGridMapping::modalShearForce: built without the shear operators (options.shear)");
    if (modalShearZ_.size() == 0) throw std::logic_error("MovingGridMapping::modalShearForce: setModes first");
    Eigen::VectorXd g;
    applyShear(modalShearZ_, modalShearTheta_, tauZ, tauTheta, offset, g);
    return g;
}

Eigen::VectorXd MovingGridMapping::fixedPressure(const Eigen::VectorXd& p, double offset) const {
    Eigen::VectorXd c;
    const Window w = project(p, offset, c);
    Eigen::VectorXd all = Eigen::VectorXd::Zero(fixed_.size());
    all.segment(static_cast<Eigen::Index>(w.k0) * nTheta_, c.size()) = c;
    return all;
}

Eigen::VectorXd MovingGridMapping::loads(const Eigen::VectorXd& p, double offset) const {
    Eigen::VectorXd f;
    loads(p, offset, f);
    return f;
}

void MovingGridMapping::loads(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& forces) const {
    Eigen::VectorXd c;
    const Window w = project(p, offset, c);
    forces.noalias() = load_.matrix().middleCols(static_cast<Eigen::Index>(w.k0) * nTheta_, c.size()) * c;
}

Eigen::VectorXd MovingGridMapping::radialDisplacement(const Eigen::VectorXd& u, double offset) const {
    Eigen::VectorXd ur;
    radialDisplacement(u, offset, ur);
    return ur;
}

void MovingGridMapping::interpolation(double offset, std::vector<std::array<double, 4>>& weights,
                                      std::vector<int>& base, int& r0, int& r1) const {
    checkOffset(offset);
    const int nz = static_cast<int>(z_.size()), nZ = fixed_.nAxial();
    const double Z0 = fixed_.axial().front(), h = h_;
    // Cubic Hermite in z on G for the point at t ∈ [0, 1] of cell k: weights of rows k−1 .. k+2
    // (those outside G stay zero); slopes m_k = (f_{k+1} − f_{k−1})/2h, one-sided
    // ∓(3f_k − 4f_{k±1} + f_{k±2})/2h at G's ends (all exact for quadratics).
    auto slope = [&](int k, std::array<double, 4>& wgt, int first, double coef) {  // adds coef · h m_k
        auto add = [&](int r, double v) {  // r − first ∈ [0, 3] always; the check keeps -Warray-bounds quiet
            const int j = r - first;
            if (j >= 0 && j < 4) wgt[static_cast<std::size_t>(j)] += v * coef;
        };
        if (k == 0) {
            add(0, -1.5), add(1, 2.0), add(2, -0.5);
        } else if (k == nZ - 1) {
            add(k, 1.5), add(k - 1, -2.0), add(k - 2, 0.5);
        } else {
            add(k + 1, 0.5), add(k - 1, -0.5);
        }
    };
    weights.assign(static_cast<std::size_t>(nz), {});
    base.assign(static_cast<std::size_t>(nz), 0);
    r0 = nZ;
    r1 = 0;
    for (int i = 0; i < nz; ++i) {
        const double x = z_[static_cast<std::size_t>(i)] + offset;
        const int k = std::clamp(static_cast<int>(std::floor((x - Z0) / h)), 0, nZ - 2);
        const double t = std::clamp((x - (Z0 + k * h)) / h, 0.0, 1.0);
        auto& wgt = weights[static_cast<std::size_t>(i)];
        wgt.fill(0.0);
        const int b = k - 1;
        base[static_cast<std::size_t>(i)] = b;
        const double t2 = t * t, t3 = t2 * t;
        wgt[1] += 2 * t3 - 3 * t2 + 1;             // h00 (row k)
        wgt[2] += -2 * t3 + 3 * t2;                // h01 (row k + 1)
        slope(k, wgt, b, t3 - 2 * t2 + t);         // h10
        slope(k + 1, wgt, b, t3 - t2);             // h11
        r0 = std::min(r0, std::max(0, b));
        r1 = std::max(r1, std::min(nZ - 1, b + 3));
    }
}

void MovingGridMapping::interpolate(const std::vector<std::array<double, 4>>& weights, const std::vector<int>& base,
                                    int r0, const Eigen::VectorXd& uG, Eigen::VectorXd& ur) const {
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nZ = fixed_.nAxial();
    ur.resize(static_cast<Eigen::Index>(nz) * nt);
    for (int i = 0; i < nz; ++i) {
        auto out = ur.segment(static_cast<Eigen::Index>(i) * nt, nt);
        out.setZero();
        const auto& wgt = weights[static_cast<std::size_t>(i)];
        for (int a = 0; a < 4; ++a) {
            const int r = base[static_cast<std::size_t>(i)] + a;
            if (r >= 0 && r < nZ && wgt[static_cast<std::size_t>(a)] != 0.0)
                out += wgt[static_cast<std::size_t>(a)] * uG.segment(static_cast<Eigen::Index>(r - r0) * nt, nt);
        }
    }
}

void MovingGridMapping::radialDisplacement(const Eigen::VectorXd& u, double offset, Eigen::VectorXd& ur) const {
    std::vector<std::array<double, 4>> weights;
    std::vector<int> base;
    int r0 = 0, r1 = 0;
    interpolation(offset, weights, base, r0, r1);
    const Eigen::Index nt = nTheta_;
    const Eigen::VectorXd uG = def_.radial().middleRows(r0 * nt, (r1 - r0 + 1) * nt) * u;
    interpolate(weights, base, r0, uG, ur);
}

void MovingGridMapping::setModes(const Eigen::MatrixXd& shapes, std::vector<int> columns) {
    if (shapes.rows() != load_.matrix().rows())
        throw std::invalid_argument("MovingGridMapping::setModes: " + std::to_string(shapes.rows()) +
                                    " dofs in the mode shapes, " + std::to_string(load_.matrix().rows()) +
                                    " in the mesh");
    const int nt = nTheta_, nZ = fixed_.nAxial();
    if (columns.empty()) {
        columns.resize(static_cast<std::size_t>(nt));
        for (int j = 0; j < nt; ++j) columns[static_cast<std::size_t>(j)] = j;
    }
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c] < 0 || columns[c] >= nt || (c > 0 && columns[c] <= columns[c - 1]))
            throw std::invalid_argument("MovingGridMapping::setModes: θ column " + std::to_string(columns[c]) +
                                        " is out of range (0.." + std::to_string(nt - 1) + ") or not ascending");
    const int nc = static_cast<int>(columns.size());
    const Eigen::Index m = shapes.cols();

    // L = Φᵀ A_G (modes × G nodes), then L M_G⁻¹ (M_G symmetric): the Thomas algorithm of solve()
    // along G's rows for every (mode, θ) pair, on blocks of nθ columns, with the Gram matrix of
    // all of G's hats (the window's truncation in solve() differs from it by ≈ 0.27³⁰).
    Eigen::MatrixXd L = (load_.matrix().transpose() * shapes).transpose();
    {
        const double h = h_, off = h / 6.0;
        std::vector<double> diag(static_cast<std::size_t>(nZ));
        for (int k = 0; k < nZ; ++k) diag[static_cast<std::size_t>(k)] = (k == 0 || k == nZ - 1) ? h / 3.0 : 2.0 * h / 3.0;
        auto block = [&](int k) { return L.middleCols(static_cast<Eigen::Index>(k) * nt, nt); };
        for (int k = 1; k < nZ; ++k) {
            const double f = off / diag[static_cast<std::size_t>(k - 1)];
            diag[static_cast<std::size_t>(k)] -= f * off;
            block(k) -= f * block(k - 1);
        }
        block(nZ - 1) /= diag[static_cast<std::size_t>(nZ - 1)];
        for (int k = nZ - 2; k >= 0; --k)
            block(k) = (block(k) - off * block(k + 1)) / diag[static_cast<std::size_t>(k)];
    }
    const Eigen::MatrixXd S = def_.radial() * shapes;  // G nodes × modes
    modalLoad_.resize(m, static_cast<Eigen::Index>(nZ) * nc);
    modalShapes_.resize(static_cast<Eigen::Index>(nZ) * nc, m);
    for (int k = 0; k < nZ; ++k)
        for (int c = 0; c < nc; ++c) {
            const Eigen::Index to = static_cast<Eigen::Index>(k) * nc + c;
            const Eigen::Index from = static_cast<Eigen::Index>(k) * nt + columns[static_cast<std::size_t>(c)];
            modalLoad_.col(to) = L.col(from);
            modalShapes_.row(to) = S.row(from);
        }
    columns_ = std::move(columns);
    if (hasShear()) {
        modalShearZ_ = (load_.axialShear().transpose() * shapes).transpose();
        modalShearTheta_ = (load_.circumferentialShear().transpose() * shapes).transpose();
    }
}

Eigen::VectorXd MovingGridMapping::modalForce(const Eigen::VectorXd& p, double offset) const {
    Eigen::VectorXd out;
    modalForce(p, offset, out);
    return out;
}

std::pair<int, int> MovingGridMapping::overlapRows(const Window& w, const Transfer& T) {
    int first = w.rows, last = -1;
    for (int r = 0; r < w.rows; ++r)
        if (T.outerIndexPtr()[r + 1] > T.outerIndexPtr()[r]) {
            first = std::min(first, r);
            last = r;
        }
    return {first, last};
}

void MovingGridMapping::modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& out) const {
    if (modalLoad_.size() == 0) throw std::logic_error("MovingGridMapping::modalForce: setModes first");
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nc = static_cast<int>(columns_.size());
    requirePressures(p.size());
    Transfer T;
    const Window w = transfer(offset, T);
    // b = T p on the active columns; Φᵀ A_G M_G⁻¹ b needs only the rows of G the grid overlaps.
    const auto [first, last] = overlapRows(w, T);
    out.setZero(modalLoad_.rows());
    if (last < first) return;
    using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    RowMat P(nz, nc);
    for (int i = 0; i < nz; ++i)
        for (int c = 0; c < nc; ++c)
            P(i, c) = p[static_cast<Eigen::Index>(i) * nt + columns_[static_cast<std::size_t>(c)]];
    const int rows = last - first + 1;
    RowMat B(rows, nc);
    B.noalias() = T.middleRows(first, rows) * P;
    out.noalias() = modalLoad_.middleCols(static_cast<Eigen::Index>(w.k0 + first) * nc, B.size()) *
                    Eigen::Map<const Eigen::VectorXd>(B.data(), B.size());
}

void MovingGridMapping::modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& out) const {
    if (modalLoad_.size() == 0) throw std::logic_error("MovingGridMapping::modalForces: setModes first");
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nc = static_cast<int>(columns_.size());
    requirePressures(P.rows());
    Transfer T;
    const Window w = transfer(offset, T);
    const auto [first, last] = overlapRows(w, T);
    out.setZero(modalLoad_.rows(), P.cols());
    if (last < first) return;
    // As modalForce, column by column into one (rows · nc) × k block, then one product.
    using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const int rows = last - first + 1;
    Eigen::MatrixXd Bs(static_cast<Eigen::Index>(rows) * nc, P.cols());
    RowMat Pc(nz, nc), B(rows, nc);
    for (Eigen::Index k = 0; k < P.cols(); ++k) {
        for (int i = 0; i < nz; ++i)
            for (int c = 0; c < nc; ++c)
                Pc(i, c) = P(static_cast<Eigen::Index>(i) * nt + columns_[static_cast<std::size_t>(c)], k);
        B.noalias() = T.middleRows(first, rows) * Pc;
        Bs.col(k) = Eigen::Map<const Eigen::VectorXd>(B.data(), B.size());
    }
    out.noalias() = modalLoad_.middleCols(static_cast<Eigen::Index>(w.k0 + first) * nc, Bs.rows()) * Bs;
}

void MovingGridMapping::modalRadialShapes(double offset, Eigen::MatrixXd& ur) const {
    if (modalShapes_.size() == 0) throw std::logic_error("MovingGridMapping::modalRadialShapes: setModes first");
    std::vector<std::array<double, 4>> weights;
    std::vector<int> base;
    int r0 = 0, r1 = 0;
    interpolation(offset, weights, base, r0, r1);
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nZ = fixed_.nAxial(), nc = static_cast<int>(columns_.size());
    ur.setZero(static_cast<Eigen::Index>(nz) * nt, modalShapes_.cols());
    for (int i = 0; i < nz; ++i) {
        const auto& wgt = weights[static_cast<std::size_t>(i)];
        for (int a = 0; a < 4; ++a) {
            const int r = base[static_cast<std::size_t>(i)] + a;
            const double wa = wgt[static_cast<std::size_t>(a)];
            if (r < 0 || r >= nZ || wa == 0.0) continue;
            for (int c = 0; c < nc; ++c)
                ur.row(static_cast<Eigen::Index>(i) * nt + columns_[static_cast<std::size_t>(c)]) +=
                    wa * modalShapes_.row(static_cast<Eigen::Index>(r) * nc + c);
        }
    }
}

Eigen::VectorXd MovingGridMapping::modalRadialDisplacement(const Eigen::VectorXd& q, double offset) const {
    Eigen::VectorXd ur;
    modalRadialDisplacement(q, offset, ur);
    return ur;
}

void MovingGridMapping::modalRadialDisplacement(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& ur) const {
    if (modalShapes_.size() == 0)
        throw std::logic_error("MovingGridMapping::modalRadialDisplacement: setModes first");
    if (q.size() != modalShapes_.cols())
        throw std::invalid_argument("MovingGridMapping::modalRadialDisplacement: " + std::to_string(q.size()) +
                                    " modal coordinates for " + std::to_string(modalShapes_.cols()) + " modes");
    std::vector<std::array<double, 4>> weights;
    std::vector<int> base;
    int r0 = 0, r1 = 0;
    interpolation(offset, weights, base, r0, r1);
    const int nz = static_cast<int>(z_.size()), nt = nTheta_, nZ = fixed_.nAxial(), nc = static_cast<int>(columns_.size());
    const Eigen::VectorXd uG = modalShapes_.middleRows(static_cast<Eigen::Index>(r0) * nc,
                                                       static_cast<Eigen::Index>(r1 - r0 + 1) * nc) * q;
    ur.setZero(static_cast<Eigen::Index>(nz) * nt);
    for (int i = 0; i < nz; ++i) {
        double* out = ur.data() + static_cast<Eigen::Index>(i) * nt;
        const auto& wgt = weights[static_cast<std::size_t>(i)];
        for (int a = 0; a < 4; ++a) {
            const int r = base[static_cast<std::size_t>(i)] + a;
            const double wa = wgt[static_cast<std::size_t>(a)];
            if (r < 0 || r >= nZ || wa == 0.0) continue;
            const double* in = uG.data() + static_cast<Eigen::Index>(r - r0) * nc;
            for (int c = 0; c < nc; ++c) out[columns_[static_cast<std::size_t>(c)]] += wa * in[c];
        }
    }
}

}  // namespace flexehd::cosim
