#pragma once
// ReynoldsSystem: the conservative finite-volume discretisation of the Reynolds equation
// (seed eq. 1) on a FilmGrid, written as the linear system A p = b of the mass balance of
// every node's control volume V_k:
//
//   Σ_faces f  [ c_f (p_k − p_nb) + m_f ]  + A_k ρ_k ∂h_k/∂t = 0,
//   c_f = ρ_f h_f³ L_f / (12 η_f d_f)        (Poiseuille conductance, kg/(s·Pa))
//   m_f = (U_n/2) ρ_f h_f L_f                (Couette mass flux out of V_k, kg/s)
//
// with face values h_f = (h_k + h_nb)/2 (central, second order), L_f the face length and d_f
// the node distance. Rows of Fixed and Void nodes are identity rows (p = prescribed); their
// columns are eliminated into b, so A is symmetric positive definite and an M-matrix.
//
// Cavitation (Reynolds/Swift–Stieber) turns it into the linear complementarity problem
//   p ≥ p_cav,  w = A p − b ≥ 0,  (p − p_cav)·w = 0      on Film nodes,
// solved by PsorSolver or ActiveSetSolver. Convergence criterion (docs/lube.md §3): the
// natural residual r_k = min(p_k − p_cav, w_k / A_kk) in pascals, relative to the pressure scale:
//   residual = max_k |r_k| / max_k |p_k − p_ambient|.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/LargeArrayAllocator.hpp"

namespace flexehd::lube {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Visits every face of the node-centred control volumes once: visit(a, b, axial, L, d) with b
/// the neighbour of a in +z (axial == true) or +θ, L the face length (m), d the distance (m; to
/// the arc end where a face borders a column cut by it, FilmGrid::faceAngle).
/// Faces between two Void nodes carry no film and are skipped.
template <class Visit>
void forEachFace(const FilmGrid& g, Visit&& visit) {
    const int nz = g.nAxial(), nt = g.nTheta();
    const double R = g.radius();
    for (int i = 0; i < nz; ++i) {
        for (int j = 0; j < nt; ++j) {
            const int a = g.index(i, j);
            if (i + 1 < nz) {
                const int b = g.index(i + 1, j);
                if (!(g.kind(a) == NodeKind::Void && g.kind(b) == NodeKind::Void))
                    visit(a, b, true, R * g.angularWidth(j), g.z(i + 1) - g.z(i));
            }
            if (j + 1 < nt || g.periodic()) {
                const int b = g.index(i, (j + 1) % nt);
                if (!(g.kind(a) == NodeKind::Void && g.kind(b) == NodeKind::Void))
                    visit(a, b, false, g.axialWidth(i), R * g.faceAngle(j));
            }
        }
    }
}

/// Face value of a nodal field: the mean of both nodes, or, where the face borders a Void node
/// (the film ends there; a mask's values are not used), the film node's value — extrapolated
/// from its other circumferential neighbour to the face's middle on a grid restricted to arcs
/// (FilmGrid::restrictToArcs), where the face reaches only to the arc's end: geometrically,
/// v_f (v_f/v_2)^(d/2Δθ), second order like a linear extrapolation, positive and smooth in the
/// values for the positive fields (h, η, ρ); v_f where either value is not positive
/// (a cavitated film fraction; docs/lube.md §1).
inline double faceValue(const FilmGrid& g, const double* v, int a, int b) {
    const bool voidA = g.kind(a) == NodeKind::Void, voidB = g.kind(b) == NodeKind::Void;
    if (!voidA && !voidB) return 0.5 * (v[a] + v[b]);
    const int f = voidA ? b : a, o = voidA ? a : b;
    const int nt = g.nTheta(), i = g.axialIndex(f), jf = g.thetaIndex(f), jo = g.thetaIndex(o);
    if (g.arcs().empty() || g.axialIndex(o) != i) return v[f];
    const bool voidEast = jo == (jf + 1) % nt;
    const int j2 = voidEast ? jf - 1 : jf + 1;  // the film side's other neighbour
    if (!g.periodic() && (j2 < 0 || j2 >= nt)) return v[f];
    const int f2 = g.index(i, (j2 + nt) % nt);
    if (g.kind(f2) == NodeKind::Void) return v[f];
    if (!(v[f] > 0.0) || !(v[f2] > 0.0)) return v[f];
    const double d = g.faceAngle(voidEast ? jf : jo);  // film node to the arc end
    return v[f] * std::pow(v[f] / v[f2], 0.5 * d / g.dTheta());
}
inline double faceValue(const FilmGrid& g, const Eigen::VectorXd& v, int a, int b) {
    return faceValue(g, v.data(), a, b);
}

/// Throws std::invalid_argument unless the film state fits the grid: h of size N, finite and
/// positive on all non-Void nodes, dhdt empty or of size N and finite, velocities finite.
void validateFilmState(const FilmGrid& grid, const FilmState& film);

class ReynoldsSystem {
public:
    /// Assembles A and b for the nodal density ρ and viscosity η (sizes N, positive).
    ReynoldsSystem(const FilmGrid& grid, const FilmState& film, const Eigen::VectorXd& density,
                   const Eigen::VectorXd& viscosity);
    /// The same for a constant density and viscosity (positive): the same system as with
    /// constant vectors, bit for bit, without them.
    ReynoldsSystem(const FilmGrid& grid, const FilmState& film, double density, double viscosity);

    const FilmGrid& grid() const { return *grid_; }
    /// A in compressed columns (symmetric, so column k = row k). Built from the stencil on the
    /// first call (the multigrid solver works on the stencil and never needs it); not safe to
    /// call for the first time from two threads at once.
    const SparseMatrix& matrix() const;
    const Eigen::VectorXd& rhs() const { return b_; }
    /// Replaces the squeeze rate ∂h/∂t (m/s, one value per node; the Film nodes' are used) in b,
    /// the operator A unchanged: b is then that of a system assembled with this dhdt, bit for bit.
    /// Constant-density systems only (std::logic_error otherwise).
    void setSqueezeRate(const Eigen::VectorXd& dhdt);
    /// Diagonal of A (built with matrix(), same caveat).
    const Eigen::VectorXd& diagonal() const;
    /// A as a symmetric 5-point stencil, the storage A is assembled in: 3 entries per node
    /// k = (i, j), kStencilC, kStencilE, kStencilN, the couplings of row k to (i, j), (i, j+1),
    /// (i+1, j) (θ wrapped on a full circumference). The other two are their mirrors (A is
    /// symmetric): the coupling to (i, j−1) is the E entry of node (i, westStencilColumn(j)), the
    /// one to (i−1, j) the N entry of node (i−1, j) (0 for i = 0). Entries towards non-Film nodes
    /// (eliminated into b) and beyond open edges are 0 — so the E entry of the last column of an
    /// open arc, which westStencilColumn(0) names, is 0 —; non-Film rows are identities (centre 1).
    /// 3 instead of 5 doubles per node: the multigrid passes stream it, memory-bound (§7).
    const LargeVector<double>& stencil() const { return st_; }
    static constexpr int kStencilC = 0, kStencilE = 1, kStencilN = 2, kStencilSize = 3;
    /// Column whose E entry is the west coupling of column j: j − 1, or nθ − 1 for j = 0 (the
    /// periodic wrap, or on an open arc a zero entry).
    static constexpr int westStencilColumn(int j, int nt) { return j > 0 ? j - 1 : nt - 1; }
    /// True for the rows subject to the cavitation bound (Film nodes).
    bool isFilm(int k) const { return grid_->kind(k) == NodeKind::Film; }

    /// Natural residual (see header comment). pLower = −∞ for the unconstrained problem.
    double residual(const Eigen::VectorXd& p,
                    double pLower = -std::numeric_limits<double>::infinity()) const;

    /// Starting vector: prescribed pressures on Fixed/Void nodes, max(pLower, ambient) on Film.
    Eigen::VectorXd initialGuess(double pLower) const;

private:
    template <bool Constant>
    void assemble(const FilmState& film, const double* rho, const double* eta);
    void buildMatrix() const;

    const FilmGrid* grid_;
    LargeVector<double> st_;     // symmetric 5-point stencil, 3 per node (C, E, N)
    Eigen::VectorXd b_;
    Eigen::VectorXd flowRhs_;    // b without the squeeze term (constant density)
    double density_ = std::numeric_limits<double>::quiet_NaN();  // constant density, else NaN
    mutable SparseMatrix A_;     // built on demand from st_
    mutable Eigen::VectorXd diag_;
    mutable bool matrixBuilt_ = false;
};

}  // namespace flexehd::lube
