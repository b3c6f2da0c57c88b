#include "lube/FilmLoadGradient.hpp"

#include <Eigen/Geometry>

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lube/FilmNodeGeometry.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "lube/ShearStressFactor.hpp"

namespace flexehd::lube {

namespace {

// One node's force sensitivity f (N per unit) applied at r: the six load rows.
void add(FilmLoadGradient::Rows& G, int col, const Eigen::Vector3d& f, const Eigen::Vector3d& lever) {
    G.col(col).head<3>() += f;
    G.col(col).tail<3>() += lever.cross(f);
}

// G D over the rows of D that are not zero only, where they are fewer than half (a starved
// film's pressure change lives on its few full-film nodes, its contact pressure change on the
// nodes in contact): one streaming pass finds them.
void addProduct(const FilmLoadGradient::Rows& G, const Eigen::Ref<const Eigen::MatrixXd>& D, Eigen::MatrixXd& out) {
    const Eigen::Index n = D.rows();
    std::vector<char> loaded(static_cast<std::size_t>(n), 0);
    for (Eigen::Index c = 0; c < D.cols(); ++c)
        for (Eigen::Index r = 0; r < n; ++r)
            if (D(r, c) != 0.0) loaded[static_cast<std::size_t>(r)] = 1;
    std::vector<Eigen::Index> rows;
    for (Eigen::Index r = 0; r < n; ++r)
        if (loaded[static_cast<std::size_t>(r)]) rows.push_back(r);
    if (2 * static_cast<Eigen::Index>(rows.size()) >= n) {
        out.noalias() += G * D;
        return;
    }
    const auto nl = static_cast<Eigen::Index>(rows.size());
    Eigen::Matrix<double, 6, Eigen::Dynamic> Gl(6, nl);
    Eigen::MatrixXd Dl(nl, D.cols());
    for (Eigen::Index i = 0; i < nl; ++i) {
        Gl.col(i) = G.col(rows[static_cast<std::size_t>(i)]);
        Dl.row(i) = D.row(rows[static_cast<std::size_t>(i)]);
    }
    out.noalias() += Gl * Dl;
}

// G D over the nodes where G is not zero, where they are fewer than half (the shear's thickness
// dependence lives where the film carries oil).
void addSparseColumnsProduct(const FilmLoadGradient::Rows& G, const Eigen::Ref<const Eigen::MatrixXd>& D,
                             Eigen::MatrixXd& out) {
    std::vector<Eigen::Index> nodes;
    for (Eigen::Index c = 0; c < G.cols(); ++c)
        if ((G.col(c).array() != 0.0).any()) nodes.push_back(c);
    if (2 * static_cast<Eigen::Index>(nodes.size()) >= G.cols()) {
        out.noalias() += G * D;
        return;
    }
    const auto nl = static_cast<Eigen::Index>(nodes.size());
    Eigen::Matrix<double, 6, Eigen::Dynamic> Gl(6, nl);
    Eigen::MatrixXd Dl(nl, D.cols());
    for (Eigen::Index i = 0; i < nl; ++i) Gl.col(i) = G.col(nodes[static_cast<std::size_t>(i)]);
    for (Eigen::Index c = 0; c < D.cols(); ++c)  // column by column: D is column-major
        for (Eigen::Index i = 0; i < nl; ++i) Dl(i, c) = D(nodes[static_cast<std::size_t>(i)], c);
    out.noalias() += Gl * Dl;
}

// G D for D given on its nodes.
void addNodeProduct(const FilmLoadGradient::Rows& G, const NodeColumns& D, Eigen::MatrixXd& out) {
    const auto nl = static_cast<Eigen::Index>(D.nodes.size());
    if (nl == 0) return;
    Eigen::Matrix<double, 6, Eigen::Dynamic> Gl(6, nl);
    for (Eigen::Index i = 0; i < nl; ++i) Gl.col(i) = G.col(D.nodes[static_cast<std::size_t>(i)]);
    out.noalias() += Gl * D.values;
}

}  // namespace

Eigen::MatrixXd FilmLoadGradient::change(const NodeColumns& dp, const Eigen::Ref<const Eigen::MatrixXd>& dh,
                                         const NodeColumns& dpc) const {
    const Eigen::Index cols = std::max({dp.cols(), dh.cols(), dpc.cols()});
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(6, cols);
    if (dp.cols()) addNodeProduct(pressure, dp, out);
    if (dh.cols()) addSparseColumnsProduct(thickness, dh, out);
    if (dpc.cols()) addNodeProduct(contactPressure, dpc, out);
    return out;
}

Eigen::MatrixXd FilmLoadGradient::change(const Eigen::Ref<const Eigen::MatrixXd>& dp,
                                         const Eigen::Ref<const Eigen::MatrixXd>& dh,
                                         const Eigen::Ref<const Eigen::MatrixXd>& dpc) const {
    const Eigen::Index cols = std::max({dp.cols(), dh.cols(), dpc.cols()});
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(6, cols);
    if (dp.cols()) addProduct(pressure, dp, out);
    if (dh.cols()) addSparseColumnsProduct(thickness, dh, out);
    if (dpc.cols()) addProduct(contactPressure, dpc, out);
    return out;
}

FilmLoadGradient filmLoadGradient(const FilmGrid& g, const FilmState& film, const Lubricant& lub,
                                  const Eigen::VectorXd& p, const FilmIntegralOptions& opt) {
    validateFilmState(g, film);
    const int n = g.size(), nz = g.nAxial(), nt = g.nTheta();
    if (p.size() != n)
        throw std::invalid_argument("filmLoadGradient: pressure has " + std::to_string(p.size()) +
                                    " values, grid has " + std::to_string(n));
    if (opt.filmFraction && opt.filmFraction->size() != n)
        throw std::invalid_argument("filmLoadGradient: film fraction has " +
                                    std::to_string(opt.filmFraction->size()) + " values, grid has " +
                                    std::to_string(n));
    const double pAmb = g.ambientPressure();
    const double dVz = film.outer.axial - film.inner.axial;
    const double dVt = film.outer.circumferential - film.inner.circumferential;
    const double dV = std::hypot(dVz, dVt);
    const ShearStressFactor shearFactor(opt.roughness);
    FilmLoadGradient G;
    G.pressure.setZero(6, n);
    G.thickness.setZero(6, n);
    G.contactPressure.setZero(6, n);
    for (int i = 0; i < nz; ++i) {
        for (int j = 0; j < nt; ++j) {
            const int k = g.index(i, j);
            if (g.kind(k) == NodeKind::Void) continue;
            const NodeFrame f = nodeFrame(g, i, j);
            const double A = f.area, S = f.surfaceArea;  // as in integrateFilm
            const Eigen::Vector3d &er = f.er, &et = f.et, &ez = f.ez;
            const Eigen::Vector3d lever = f.position - opt.referencePoint;
            const double h = film.h[k];
            const Stencil sz = axialStencil(g, i, j), st = circumferentialStencil(g, i, j);
            const double dpdz = sz.apply(p), dpdy = st.apply(p);
            const double phi = opt.filmFraction ? (*opt.filmFraction)[k] : 1.0;
            const double pk = p[k] - pAmb;
            const double eta = lub.viscosity(pk);
            // Shear τ = φη(p)U c(h) − (h/2)∇p, c = φ_f/h (FilmIntegrals.hpp); the viscosity's slope
            // by a central difference (zero for a constant viscosity).
            double c, dcdh;
            shearFactor.couette(h, c, dcdh);
            const double dp = 1e-6 * std::max(std::abs(pk), 1e5);
            const double detaDp = (lub.viscosity(pk + dp) - lub.viscosity(pk - dp)) / (2.0 * dp);
            // ∂/∂p_k: the pressure force, and the Couette shear through η(p_k).
            add(G.pressure, k, -A * er + (phi * detaDp * c) * S * (dVz * ez + dVt * et), lever);
            // ∂/∂p at the stencil nodes: −(h/2)∇p.
            const Stencil* stencils[2] = {&sz, &st};
            const Eigen::Vector3d dirs[2] = {ez, et};
            for (int d = 0; d < 2; ++d) {
                const Stencil& q = *stencils[d];
                const Eigen::Vector3d f = -0.5 * h * S * dirs[d];
                add(G.pressure, q.m, q.wm * f, lever);
                add(G.pressure, q.o, q.wo * f, lever);
                add(G.pressure, q.p, q.wp * f, lever);
            }
            // ∂/∂h_k: φηU ∂c/∂h − ∇p/2 (smooth: −φηU/h² − ∇p/2).
            const double couette = phi * eta * dcdh;
            add(G.thickness, k, S * ((couette * dVz - 0.5 * dpdz) * ez + (couette * dVt - 0.5 * dpdy) * et), lever);
            // ∂/∂p_c,k: the contact force and the boundary friction μ_b p_c (V/|V|).
            Eigen::Vector3d fc = -S * er;
            if (dV > 0.0) fc += opt.boundaryFriction * S / dV * (dVz * ez + dVt * et);
            add(G.contactPressure, k, fc, lever);
        }
    }
    return G;
}

}  // namespace flexehd::lube
