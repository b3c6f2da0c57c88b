#pragma once
// The discrete JFO problem of lube::JfoSolver (docs/lube.md §3b): the finite-volume faces of a
// grid touching its Film nodes (JfoTopology, once per grid), the faces' coefficients for a film
// thickness and the balance of each node (JfoNetwork, once per solve), and the active-set linear
// system of a full-film / cavitated partition (JfoActiveSetSystem). Shared by the solver's
// methods and by its linearisation (JfoLinearization); not part of the library's interface.
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/JfoSolver.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube {

using JfoMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// One face of the finite-volume scheme, volumetric: flow a → b = c (p_a − p_b) + q φ_up,
// φ_up = φ_a if q > 0 else φ_b.
struct JfoFace {
    int a, b;
    double c, q;
};

// The faces of the grid's finite volumes that touch a Film node and the node → face adjacency
// (CSR, with each entry's other node, direction and whether that node is Film); the faces
// between a Film node and a boundary one: fixed for a grid, built once per solver.
struct JfoTopology {
    struct FaceGeometry {
        int a, b;
        bool axial;
        double L, d;  // face length and distance (m)
        bool interior;  // neither node Void: h_f = (h_a + h_b)/2
        int slotA, slotB;  // the face's adjacency entries of a and of b
    };
    std::vector<FaceGeometry> faces;
    std::vector<int> start, adj;
    std::vector<int> other;           // per adjacency entry: the face's other node
    std::vector<char> otherFilm;      // per adjacency entry: the other node is a Film node
    std::vector<int> boundaryFaces;   // faces with one Film and one Fixed or Void node
    std::vector<double> area;  // control-volume area per node (m²)
    std::vector<int> filmRows;   // the Film nodes, ascending
    std::vector<int> ringStart;  // per axial index i: where its Film nodes start in filmRows
    std::vector<int> otherNodes; // the Fixed and Void nodes

    explicit JfoTopology(const FilmGrid& g) {
        for (int k = 0; k < g.size(); ++k) area.push_back(g.area(k));
        ringStart.assign(static_cast<std::size_t>(g.nAxial()) + 1, 0);
        for (int k = 0; k < g.size(); ++k) {
            if (g.kind(k) != NodeKind::Film) {
                otherNodes.push_back(k);
                continue;
            }
            filmRows.push_back(k);
            ++ringStart[static_cast<std::size_t>(g.axialIndex(k)) + 1];
        }
        for (int i = 0; i < g.nAxial(); ++i)
            ringStart[static_cast<std::size_t>(i) + 1] += ringStart[static_cast<std::size_t>(i)];
        forEachFace(g, [&](int a, int b, bool axial, double L, double d) {
            if (g.kind(a) != NodeKind::Film && g.kind(b) != NodeKind::Film) return;
            faces.push_back({a, b, axial, L, d, g.kind(a) != NodeKind::Void && g.kind(b) != NodeKind::Void, -1, -1});
        });
        const int n = g.size();
        start.assign(static_cast<std::size_t>(n) + 1, 0);
        adj.resize(2 * faces.size());
        for (const FaceGeometry& f : faces) {
            ++start[static_cast<std::size_t>(f.a) + 1];
            ++start[static_cast<std::size_t>(f.b) + 1];
        }
        for (int k = 0; k < n; ++k) start[static_cast<std::size_t>(k) + 1] += start[static_cast<std::size_t>(k)];
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            faces[i].slotA = fill[static_cast<std::size_t>(faces[i].a)]++;
            faces[i].slotB = fill[static_cast<std::size_t>(faces[i].b)]++;
            adj[static_cast<std::size_t>(faces[i].slotA)] = static_cast<int>(i);
            adj[static_cast<std::size_t>(faces[i].slotB)] = static_cast<int>(i);
            if ((g.kind(faces[i].a) == NodeKind::Film) != (g.kind(faces[i].b) == NodeKind::Film))
                boundaryFaces.push_back(static_cast<int>(i));
        }
        other.resize(adj.size());
        otherFilm.resize(adj.size());
        for (int k = 0; k < n; ++k)
            for (int q = start[static_cast<std::size_t>(k)]; q < start[static_cast<std::size_t>(k) + 1]; ++q) {
                const FaceGeometry& f = faces[static_cast<std::size_t>(adj[static_cast<std::size_t>(q)])];
                const auto sq = static_cast<std::size_t>(q);
                other[sq] = f.a == k ? f.b : f.a;
                otherFilm[sq] = g.kind(other[sq]) == NodeKind::Film;
            }
    }
};

// The faces' coefficients for the film h and the viscosity eta (Pa s), and each adjacency entry's
// conductance c and Couette coefficient qo out of its node (c, qo sized to the adjacency).
inline void buildFaces(const JfoTopology& t, const FilmGrid& g, const FilmState& film, double eta,
                       std::vector<JfoFace>& faces, std::vector<double>& c, std::vector<double>& qo) {
    faces.resize(t.faces.size());
    c.resize(t.adj.size());
    qo.resize(t.adj.size());
    const double Uz = 0.5 * film.sumAxial(), Ut = 0.5 * film.sumCircumferential();
    const double* h = film.h.data();
    for (std::size_t i = 0; i < t.faces.size(); ++i) {
        const JfoTopology::FaceGeometry& f = t.faces[i];
        const double hf = f.interior ? 0.5 * (h[f.a] + h[f.b]) : faceValue(g, h, f.a, f.b);
        const double cf = hf * hf * hf * f.L / (12.0 * eta * f.d), qf = (f.axial ? Uz : Ut) * hf * f.L;
        faces[i] = {f.a, f.b, cf, qf};
        c[static_cast<std::size_t>(f.slotA)] = cf;
        c[static_cast<std::size_t>(f.slotB)] = cf;
        qo[static_cast<std::size_t>(f.slotA)] = qf;
        qo[static_cast<std::size_t>(f.slotB)] = -qf;
    }
}

// The per-solve arrays of a JfoNetwork; a solver keeps one to reuse their memory.
struct JfoNetworkStorage {
    std::vector<JfoFace> faces;
    std::vector<double> c, qo;  // per adjacency entry
    std::vector<double> D, B;   // per node: Σ c_f, and the Couette outflow plus storage
};

// The discrete JFO problem of one solve (docs/lube.md, the JFO scheme): the faces, the node → face
// adjacency and the storage terms; the balance of a node and the scaled mass residual.
class JfoNetwork {
public:
    // Balance of node k: F = D p_k − S + B φ_k − Sin (see the header).
    struct Balance { double D, S, B, Sin; };

    // storage: arrays to reuse (nullptr: the network's own).
    JfoNetwork(const JfoTopology& t, const FilmGrid& g, const FilmState& film, double eta, double dt,
               const JfoState* previous, const std::vector<double>& inlet, double pcav,
               JfoNetworkStorage* storage = nullptr)
        : g_(g), film_(film), dt_(dt), previous_(previous), inlet_(inlet), pcav_(pcav),
          s_(storage ? *storage : own_), t_(t), area_(t.area.data()) {
        buildFaces(t, g, film, eta, s_.faces, s_.c, s_.qo);
        sumPerNode();
    }

    // visit(m, c, qo) for each face of node k: its other node m, Poiseuille coefficient c and the
    // Couette coefficient qo of the flow out of k.
    template <class Visit>
    void forFaces(int k, Visit visit) const {
        const int* other = t_.other.data();
        for (int q = t_.start[static_cast<std::size_t>(k)]; q < t_.start[static_cast<std::size_t>(k) + 1]; ++q)
            visit(other[q], c_[q], qo_[q]);
    }
    const std::vector<JfoFace>& faces() const { return s_.faces; }
    const JfoTopology& topology() const { return t_; }
    // Storage V h/dt of node k and the oil V φ_prev h_prev/dt it held (0, 0 when steady).
    double storage(int k) const { return dt_ > 0.0 ? area_[k] * film_.h[k] / dt_ : 0.0; }
    double previousOil(int k) const {
        return dt_ > 0.0 ? area_[k] * previous_->fraction[k] * previous_->h[k] / dt_ : 0.0;
    }
    bool transient() const { return dt_ > 0.0; }
    double area(int k) const { return area_[k]; }
    double inlet(int m) const { return inlet_[static_cast<std::size_t>(m)]; }

    // D and B do not depend on the iterate: summed once per solve (sumPerNode), in this order.
    // With `missing`, also the Couette inflow that the upstream partial films (or starved inlets)
    // do not bring, Σ_in −q_f (1 − φ_up) (m³/s), into *missing.
    template <bool WithMissing = false>
    Balance balance(int k, const double* p, const double* phi, double* missing = nullptr) const {
        const auto sk = static_cast<std::size_t>(k);
        Balance bl{D_[sk], 0.0, B_[sk], 0.0};
        const int* other = t_.other.data();
        const char* film = t_.otherFilm.data();
        const double* cs = c_;
        const double* qos = qo_;
        double lost = 0.0;
        for (int q = t_.start[sk]; q < t_.start[sk + 1]; ++q) {
            const double qo = qos[q];
            const int m = other[q];
            bl.S += cs[q] * p[m];
            if (qo < 0.0) {
                const double up = film[q] ? phi[m] : inlet(m);  // non-Film: its inlet fraction
                bl.Sin -= qo * up;
                if constexpr (WithMissing) lost -= qo * (1.0 - up);
            }
        }
        if constexpr (WithMissing) *missing = lost;
        if (transient()) bl.Sin += previousOil(k);
        return bl;
    }

    // The convergence criterion (header): scaled mass residual of the iterate. With `missing`
    // (one value per node), each row's missing Couette inflow (balance) at the iterate, too.
    double residual(const std::vector<int>& rows, const double* p, const double* phi, double* missing = nullptr) const {
        const double pAmb = g_.ambientPressure();
        const double scale = (Eigen::Map<const Eigen::ArrayXd>(p, g_.size()) - pAmb).abs().maxCoeff();
        double rmax = 0.0;
        for (int k : rows) {
            const Balance bl = missing ? balance<true>(k, p, phi, missing + k) : balance(k, p, phi);
            const double F = bl.D * p[k] - bl.S + bl.B * phi[k] - bl.Sin;
            const bool full = phi[k] >= 1.0 && p[k] > pcav_;
            const double r = (full || !(bl.B > 0.0)) ? std::abs(F) / bl.D / std::max(scale, 1e-300)
                                                     : std::abs(F) / bl.B;
            rmax = std::max(rmax, r);
        }
        return rmax;
    }

private:
    // Per node D and B from the adjacency entries' conductances and Couette coefficients out of the
    // node (contiguous per node: the loops read these, not the faces).
    void sumPerNode() {
        const std::size_t n = t_.area.size();
        s_.D.resize(n);
        s_.B.resize(n);
        const double* cs = s_.c.data();
        const double* qos = s_.qo.data();
        for (std::size_t k = 0; k < n; ++k) {
            double d = 0.0, b = 0.0;
            for (int q = t_.start[k]; q < t_.start[k + 1]; ++q) {
                d += cs[q];
                b += std::max(qos[q], 0.0);
            }
            if (transient()) b += storage(static_cast<int>(k));
            s_.D[k] = d;
            s_.B[k] = b;
        }
        c_ = s_.c.data();
        qo_ = s_.qo.data();
        D_ = s_.D.data();
        B_ = s_.B.data();
    }

    const FilmGrid& g_;
    const FilmState& film_;
    double dt_;
    const JfoState* previous_;
    const std::vector<double>& inlet_;
    double pcav_;
    JfoNetworkStorage own_;
    JfoNetworkStorage& s_;
    const JfoTopology& t_;
    const double* area_;
    const double *c_ = nullptr, *qo_ = nullptr, *D_ = nullptr, *B_ = nullptr;
};


// The active-set linear system over a set of Film nodes (all of them, or a part with the others
// held). Unknown of row node k: p_k (full film) or φ_k (cavitated). Row k is the balance
// F_k = D p_k − Σ c_f p_m + B φ_k − Σ_in a_f φ_m − s_k = 0 (B: Couette outflow + storage, a_f:
// Couette inflow coefficients, s_k: previous oil); known p, φ (the other state's variable,
// non-Film neighbours with their inlet fraction, Film nodes outside the rows with their p and φ)
// go to the right-hand side. The matrix's pattern is fixed; each partition rewrites its values
// through the kept pointers.
class JfoActiveSetSystem {
public:
    JfoActiveSetSystem(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const double* p,
                       const double* phi)
        : nf_(static_cast<int>(rows.size())) {
        const int n = g.size();
        idx_.assign(static_cast<std::size_t>(n), -1);
        for (int r = 0; r < nf_; ++r) idx_[static_cast<std::size_t>(rows[static_cast<std::size_t>(r)])] = r;
        linkStart_.assign(static_cast<std::size_t>(nf_) + 1, 0);
        D_.resize(static_cast<std::size_t>(nf_));
        B_.resize(static_cast<std::size_t>(nf_));
        known_.resize(static_cast<std::size_t>(nf_));
        store_.resize(static_cast<std::size_t>(nf_));
        std::vector<Eigen::Triplet<double, int>> trip;
        for (int r = 0; r < nf_; ++r) {
            const int k = rows[static_cast<std::size_t>(r)];
            double d = 0.0, b = 0.0, kn = 0.0;
            net.forFaces(k, [&](int m, double c, double qo) {
                d += c;
                const double a = qo > 0.0 ? 0.0 : -qo;
                if (qo > 0.0) b += qo;
                if (idx_[static_cast<std::size_t>(m)] >= 0) {
                    links_.push_back({m, c, a, nullptr});
                    trip.emplace_back(r, idx_[static_cast<std::size_t>(m)], 0.0);
                } else {  // a boundary node, or a Film node outside the rows (held: its p and φ)
                    kn -= c * p[m] + a * (g.kind(m) == NodeKind::Film ? phi[m] : net.inlet(m));
                }
            });
            b += net.storage(k);
            D_[static_cast<std::size_t>(r)] = d;
            B_[static_cast<std::size_t>(r)] = b;
            known_[static_cast<std::size_t>(r)] = kn;
            store_[static_cast<std::size_t>(r)] = net.previousOil(k);
            trip.emplace_back(r, r, 0.0);
            linkStart_[static_cast<std::size_t>(r) + 1] = static_cast<int>(links_.size());
        }
        M_.resize(nf_, nf_);
        M_.setFromTriplets(trip.begin(), trip.end());
        M_.makeCompressed();
        diag_.resize(static_cast<std::size_t>(nf_));
        for (int r = 0; r < nf_; ++r) {
            diag_[static_cast<std::size_t>(r)] = &M_.coeffRef(r, r);
            for (int l = linkStart_[static_cast<std::size_t>(r)]; l < linkStart_[static_cast<std::size_t>(r) + 1]; ++l)
                links_[static_cast<std::size_t>(l)].value =
                    &M_.coeffRef(r, idx_[static_cast<std::size_t>(links_[static_cast<std::size_t>(l)].m)]);
        }
    }

    int size() const { return nf_; }
    double B(int r) const { return B_[static_cast<std::size_t>(r)]; }

    // The matrix and right-hand side of the partition cav (1: cavitated row).
    void setPartition(const std::vector<char>& cav, double pcav, Eigen::VectorXd& rhs) {
        rhs.resize(nf_);
        for (int r = 0; r < nf_; ++r) {
            const auto sr = static_cast<std::size_t>(r);
            const bool c = cav[sr];
            *diag_[sr] = c ? B_[sr] : D_[sr];
            double kn = known_[sr] + (c ? D_[sr] * pcav : B_[sr]);  // p_k = p_cav, or φ_k = 1
            for (int l = linkStart_[sr]; l < linkStart_[sr + 1]; ++l) {
                Link& lk = links_[static_cast<std::size_t>(l)];
                if (cav[static_cast<std::size_t>(idx_[static_cast<std::size_t>(lk.m)])]) {
                    *lk.value = -lk.a;
                    kn -= lk.c * pcav;
                } else {
                    *lk.value = -lk.c;
                    kn -= lk.a;
                }
            }
            rhs[r] = store_[sr] - kn;
        }
    }
    const JfoMatrix& matrix() const { return M_; }

private:
    struct Link { int m; double c, a; double* value; };  // neighbour, Poiseuille, inflow Couette
    int nf_;
    std::vector<int> idx_, linkStart_;
    std::vector<Link> links_;
    std::vector<double> D_, B_, known_, store_;
    JfoMatrix M_;
    std::vector<double*> diag_;
};

}  // namespace flexehd::lube
