#include "cosim/mapping/DeformationMapping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include <Eigen/LU>
#include <Eigen/QR>

#include "fem/BoundarySurface.hpp"

namespace flexehd::cosim {
namespace {

constexpr double kPi = 3.14159265358979323846;
using V2 = Eigen::Vector2d;  // (z, s = R θ)

double wrap(double a) { return a - 2.0 * kPi * std::round(a / (2.0 * kPi)); }

// Clough–Tocher macro-triangle on V[0..2] with vertex values f and gradients g (in (z, s)),
// evaluated at P (Bézier form, split at the centroid).
double cloughTocher(const std::array<V2, 3>& V, const std::array<double, 3>& f,
                    const std::array<V2, 3>& g, const V2& P) {
    const V2 C = (V[0] + V[1] + V[2]) / 3.0;
    std::array<double, 3> a{};  // ordinate at V_i + (C − V_i)/3 (tangent plane at V_i)
    for (int i = 0; i < 3; ++i) a[i] = f[i] + g[i].dot(C - V[i]) / 3.0;
    auto edgeOrd = [&](int i, int j) { return f[i] + g[i].dot(V[j] - V[i]) / 3.0; };
    // m[i]: ordinate at (V_i + V_j + C)/3 of sub-triangle (V_i, V_j, C), j = i + 1: the normal
    // derivative along edge V_iV_j is made linear in the vertex gradients (C¹ across the edge).
    std::array<double, 3> m{};
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const V2 e = V[j] - V[i];
        V2 d(-e(1), e(0));
        d.normalize();
        if (d.dot(C - V[i]) < 0.0) d = -d;
        // d = δj (V_j − V_i) + δc (C − V_i), δi = −δj − δc.
        Eigen::Matrix2d M;
        M.col(0) = e;
        M.col(1) = C - V[i];
        const V2 dl = M.inverse() * d;
        const double dj = dl(0), dc = dl(1), di = -dj - dc;
        m[i] = ((g[i].dot(d) + g[j].dot(d)) / 6.0 - edgeOrd(i, j) * di - edgeOrd(j, i) * dj) / dc;
    }
    // q[i]: ordinate at (V_i + 2C)/3 on the split edge V_i–C (C¹ between sub-triangles), centre.
    std::array<double, 3> q{};
    for (int i = 0; i < 3; ++i) q[i] = (m[i] + m[(i + 2) % 3] + a[i]) / 3.0;
    const double centre = (q[0] + q[1] + q[2]) / 3.0;

    // Sub-triangle containing P: the one opposite the vertex with the smallest barycentric.
    Eigen::Matrix2d T;
    T.col(0) = V[1] - V[0];
    T.col(1) = V[2] - V[0];
    const V2 l12 = T.inverse() * (P - V[0]);
    const std::array<double, 3> lam = {1.0 - l12(0) - l12(1), l12(0), l12(1)};
    const int k = static_cast<int>(std::min_element(lam.begin(), lam.end()) - lam.begin());
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double u = lam[i] - lam[k], v = lam[j] - lam[k], w = 3.0 * lam[k];
    // Ordinates of the cubic on (V_i, V_j, C), b_abc with a + b + c = 3.
    const double b300 = f[i], b030 = f[j], b003 = centre;
    const double b210 = edgeOrd(i, j), b120 = edgeOrd(j, i);
    const double b201 = a[i], b021 = a[j];
    const double b111 = m[i];  // sub-triangle (V_i, V_j, C) with j = i + 1
    const double b102 = q[i], b012 = q[j];
    return b300 * u * u * u + b030 * v * v * v + b003 * w * w * w +
           3.0 * (b210 * u * u * v + b120 * u * v * v + b201 * u * u * w + b021 * v * v * w +
                  b102 * u * w * w + b012 * v * w * w) +
           6.0 * b111 * u * v * w;
}

struct Stencil {
    std::vector<std::pair<int, V2>> terms;  // node, weight of its value in (∂/∂z, ∂/∂s)
};

}  // namespace

namespace {

// Throws unless the surface's nodes lie on a cylinder about z within the relative tolerance.
void requireCylinder(const fem::Mesh& mesh, const std::string& surface, const std::vector<fem::Index>& nodes,
                     double radiusTolerance) {
    double rMin = std::numeric_limits<double>::infinity(), rMax = 0.0, rSum = 0.0;
    for (fem::Index n : nodes) {
        const double r = mesh.nodes.col(n).head<2>().norm();
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
        rSum += r;
    }
    const double spread = (rMax - rMin) / (rSum / static_cast<double>(nodes.size()));
    if (!(spread <= radiusTolerance))
        throw std::invalid_argument("surface '" + surface + "' is not a cylinder about z (relative radius spread " +
                                    std::to_string(spread) + " > tolerance " +
                                    std::to_string(radiusTolerance) + ")");
}

// The surface in the film's (z, s = R θ) coordinates: its triangles, the triangles around each
// vertex, and each node's θ.
struct SurfaceImage {
    const fem::Mesh& mesh;
    double axialOffset, R;
    std::vector<double> th;                         // θ per mesh node (surface nodes only)
    std::vector<std::vector<fem::Index>> around;    // triangles around each vertex
    double z(int n) const { return mesh.nodes(2, n) - axialOffset; }
};

// Gradient stencil at vertex v: least-squares quadratic in (z, s) over one ring of triangles
// (two if fewer than 10 nodes).
Stencil gradientStencil(const SurfaceImage& im, const std::string& surface, fem::Index v) {
    const fem::Mesh& mesh = im.mesh;
    const int npe = static_cast<int>(mesh.surface.nodes.rows());
    Stencil stencil;
    const auto& ring = im.around[static_cast<std::size_t>(v)];
    if (ring.empty()) return stencil;
    std::set<int> pts;
    for (fem::Index t : ring)
        for (int a = 0; a < npe; ++a) pts.insert(mesh.surface.nodes(a, t));
    if (pts.size() < 10) {
        const std::set<int> first = pts;
        for (int w : first)
            for (fem::Index t : im.around[static_cast<std::size_t>(w)])
                for (int a = 0; a < npe; ++a) pts.insert(mesh.surface.nodes(a, t));
    }
    std::vector<int> ids(pts.begin(), pts.end());
    std::vector<V2> x;
    double h = 0.0;
    for (int n : ids) {
        x.emplace_back(im.z(n) - im.z(v),
                       im.R * wrap(im.th[static_cast<std::size_t>(n)] - im.th[static_cast<std::size_t>(v)]));
        h = std::max(h, x.back().norm());
    }
    Eigen::MatrixXd A(static_cast<Eigen::Index>(ids.size()), 6);
    for (std::size_t r = 0; r < ids.size(); ++r) {
        const double X = x[r](0) / h, Y = x[r](1) / h;
        A.row(static_cast<Eigen::Index>(r)) << 1.0, X, Y, X * X, X * Y, Y * Y;
    }
    const Eigen::MatrixXd Pinv = A.completeOrthogonalDecomposition().pseudoInverse();
    if (A.completeOrthogonalDecomposition().rank() < 6)
        throw std::runtime_error("too few nodes of surface '" + surface + "' around its node " +
                                 std::to_string(mesh.nodeTags[static_cast<std::size_t>(v)]) +
                                 " for a quadratic gradient fit");
    for (std::size_t r = 0; r < ids.size(); ++r)
        stencil.terms.emplace_back(ids[r], V2(Pinv(1, static_cast<Eigen::Index>(r)) / h,
                                              Pinv(2, static_cast<Eigen::Index>(r)) / h));
    return stencil;
}

// The interpolation weights of the grid nodes inside triangle t's image (those not yet done: the
// first triangle wins on shared edges), by unit inputs of the Clough–Tocher interpolant, which is
// linear in the vertex values and gradients (the gradients by their stencils).
void interpolateInTriangle(const SurfaceImage& im, const std::vector<Stencil>& grad, const lube::FilmGrid& grid,
                           fem::Index t, std::vector<char>& done, std::vector<Eigen::Triplet<double>>& trip) {
    const std::vector<double>& zg = grid.axial();
    const double th0 = grid.theta(0), dTh = grid.dTheta(), R = im.R;
    const int nt = grid.nTheta();
    std::array<int, 3> vid{};
    std::array<V2, 3> V;
    std::array<double, 3> tq{};
    for (int a = 0; a < 3; ++a) {
        vid[a] = im.mesh.surface.nodes(a, t);
        tq[a] = im.th[static_cast<std::size_t>(vid[0])] +
                wrap(im.th[static_cast<std::size_t>(vid[a])] - im.th[static_cast<std::size_t>(vid[0])]);
        V[a] = V2(im.z(vid[a]), R * tq[a]);
    }
    const double zlo = std::min({V[0](0), V[1](0), V[2](0)}), zhi = std::max({V[0](0), V[1](0), V[2](0)});
    const double tlo = *std::min_element(tq.begin(), tq.end()), thi = *std::max_element(tq.begin(), tq.end());
    Eigen::Matrix2d T;
    T.col(0) = V[1] - V[0];
    T.col(1) = V[2] - V[0];
    const Eigen::Matrix2d Tinv = T.inverse();
    const double eps = 1e-10;
    const auto i0 = std::lower_bound(zg.begin(), zg.end(), zlo - eps * (zhi - zlo)) - zg.begin();
    const auto i1 = std::upper_bound(zg.begin(), zg.end(), zhi + eps * (zhi - zlo)) - zg.begin();
    for (int sh = grid.periodic() ? 0 : -1; sh <= (grid.periodic() ? 0 : 1); ++sh) {
        const double off = 2.0 * kPi * sh;
        const int c0 = static_cast<int>(std::ceil((tlo + off - th0) / dTh - 1e-9));
        const int c1 = static_cast<int>(std::floor((thi + off - th0) / dTh + 1e-9));
        for (int c = c0; c <= c1; ++c) {
            if (!grid.periodic() && (c < 0 || c >= nt)) continue;
            const int j = ((c % nt) + nt) % nt;
            for (auto i = i0; i < i1; ++i) {
                const int k = grid.index(static_cast<int>(i), j);
                if (done[static_cast<std::size_t>(k)]) continue;
                const V2 P(zg[static_cast<std::size_t>(i)], R * (th0 + c * dTh - off));
                const V2 l = Tinv * (P - V[0]);
                if (l(0) < -eps || l(1) < -eps || l(0) + l(1) > 1.0 + eps) continue;
                done[static_cast<std::size_t>(k)] = 1;
                std::array<double, 3> f{};
                std::array<V2, 3> g{V2::Zero(), V2::Zero(), V2::Zero()};
                for (int a = 0; a < 3; ++a) {
                    f = {0.0, 0.0, 0.0};
                    f[a] = 1.0;
                    trip.emplace_back(k, vid[a], cloughTocher(V, f, g, P));
                    f[a] = 0.0;
                    for (int d = 0; d < 2; ++d) {
                        g[a](d) = 1.0;
                        const double w = cloughTocher(V, f, g, P);
                        g[a](d) = 0.0;
                        for (const auto& [n, gw] : grad[static_cast<std::size_t>(vid[a])].terms)
                            trip.emplace_back(k, n, w * gw(d));
                    }
                }
            }
        }
    }
}

}  // namespace

DeformationMapping::DeformationMapping(const fem::Mesh& mesh, const std::string& surface,
                                       const lube::FilmGrid& grid, double axialOffset,
                                       double radiusTolerance) {
    const fem::BoundarySurface surf(mesh, surface);
    const std::vector<fem::Index> nodes = mesh.groupNodes(surface);
    requireCylinder(mesh, surface, nodes, radiusTolerance);
    const int nn = mesh.numNodes();
    SurfaceImage im{mesh, axialOffset, grid.radius(), std::vector<double>(static_cast<std::size_t>(nn), 0.0),
                    std::vector<std::vector<fem::Index>>(static_cast<std::size_t>(nn))};
    for (fem::Index n : nodes) im.th[static_cast<std::size_t>(n)] = std::atan2(mesh.nodes(1, n), mesh.nodes(0, n));
    const std::vector<fem::Index>& tris = surf.triangles();
    for (fem::Index t : tris)
        for (int a = 0; a < 3; ++a) im.around[static_cast<std::size_t>(mesh.surface.nodes(a, t))].push_back(t);
    std::vector<Stencil> grad(static_cast<std::size_t>(nn));
    for (fem::Index v = 0; v < nn; ++v) grad[static_cast<std::size_t>(v)] = gradientStencil(im, surface, v);

    std::vector<char> done(static_cast<std::size_t>(grid.size()), 0);
    std::vector<Eigen::Triplet<double>> trip;
    for (fem::Index t : tris) interpolateInTriangle(im, grad, grid, t, done, trip);
    for (int k = 0; k < grid.size(); ++k)
        if (!done[static_cast<std::size_t>(k)]) outside_.push_back(k);
    if (static_cast<int>(outside_.size()) == grid.size())
        throw std::invalid_argument("no film grid node lies on surface '" + surface + "'");
    S_.resize(grid.size(), nn);
    S_.setFromTriplets(trip.begin(), trip.end());
    S_.prune(0.0);
    // Radial displacement at the grid node: interpolate u_x, u_y, project on n_r(θ_grid)
    // (exact for rigid translations).
    std::vector<Eigen::Triplet<double>> rt;
    for (int k = 0; k < S_.rows(); ++k) {
        const double tk = grid.theta(grid.thetaIndex(k));
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S_, k); it; ++it) {
            rt.emplace_back(k, 3 * it.col(), it.value() * std::cos(tk));
            rt.emplace_back(k, 3 * it.col() + 1, it.value() * std::sin(tk));
        }
    }
    Rr_.resize(grid.size(), 3 * nn);
    Rr_.setFromTriplets(rt.begin(), rt.end());
}

}  // namespace flexehd::cosim
