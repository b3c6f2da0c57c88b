#include "cosim/mapping/LoadMapping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "fem/BoundarySurface.hpp"
#include "fem/ShapeFunctions.hpp"
#include "modal/GaussLegendre.hpp"

namespace flexehd::cosim {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Point = Eigen::Vector2d;  // (z, θ) in the parameter plane
using Polygon = std::vector<Point>;

struct RulePoint {
    double xi, eta, weight;  // reference triangle, weights sum to 1/2
};

// Collapsed (Duffy / Stroud conical product) rule on the reference triangle: ξ = u,
// η = v (1 − u), Jacobian (1 − u); exact for total degree ≤ 2n − 2.
std::vector<RulePoint> collapsedRule(int n) {
    const modal::QuadratureRule rule = modal::gaussLegendre(n);  // on [0, 1] (Abramowitz & Stegun 25.4.29)
    const std::vector<double>& x = rule.nodes;
    const std::vector<double>& w = rule.weights;
    std::vector<RulePoint> r;
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j)
            r.push_back({x[i], x[j] * (1.0 - x[i]), w[i] * w[j] * (1.0 - x[i])});
    return r;
}

// Points per direction so that the polynomial degree 4 (bilinear × quadratic N) is exact
// and the Taylor remainder of cos/sin about the centre of a cell of angular width δ,
// (δ/2)^(m+1)/(m+1)! with m = 2n − 6 the degree left for it, is below 1e-17.
int ruleOrder(double delta) {
    for (int n = 3; n < 16; ++n) {
        const int m1 = 2 * n - 5;
        double r = 1.0;
        for (int k = 1; k <= m1; ++k) r *= 0.5 * delta / k;
        if (r < 1e-17) return n;
    }
    return 16;
}

// Sutherland–Hodgman clipping of a convex polygon against coordinate c (0: z, 1: θ) ≥ bound
// (keepAbove) or ≤ bound.
Polygon clip(const Polygon& in, int c, double bound, bool keepAbove) {
    Polygon out;
    if (in.empty()) return out;
    auto inside = [&](const Point& p) { return keepAbove ? p(c) >= bound : p(c) <= bound; };
    for (std::size_t k = 0; k < in.size(); ++k) {
        const Point& a = in[k];
        const Point& b = in[(k + 1) % in.size()];
        const bool ia = inside(a), ib = inside(b);
        if (ia) out.push_back(a);
        if (ia != ib) {
            const double t = (bound - a(c)) / (b(c) - a(c));
            Point q = a + t * (b - a);
            q(c) = bound;
            out.push_back(q);
        }
    }
    return out;
}

double polygonArea(const Polygon& p) {
    double a = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Point& u = p[k];
        const Point& v = p[(k + 1) % p.size()];
        a += u(0) * v(1) - u(1) * v(0);
    }
    return 0.5 * a;
}

template <fem::ElementType T>
typename fem::Shape<T>::Values shape(double xi, double eta) {
    return fem::Shape<T>::N(Eigen::Vector3d(xi, eta, 0.0));
}

// A surface triangle and its (z, θ) image: θ unwrapped relative to vertex 0 (seam at ±π), the
// affine map ref → image (J, its inverse) and the image's extent.
template <int kN>
struct TriangleImage {
    Eigen::Matrix<double, 3, kN> X;  // vertices (and mid-edge nodes) in space
    std::array<int, kN> node{};
    std::array<Point, kN> P;         // their images (z − axialOffset, θ)
    Eigen::Matrix2d J, Jinv;
    double det = 0.0, zLo = 0.0, zHi = 0.0, tLo = 0.0, tHi = 0.0;
};

struct Setup {
    const fem::Mesh& mesh;
    const fem::BoundarySurface& surf;
    const lube::FilmGrid& grid;
    const LoadMappingOptions& opt;
    LoadMappingStats& stats;
    std::vector<Eigen::Triplet<double>>& triplets;
    std::vector<RulePoint> rule;
    std::vector<Eigen::Triplet<double>>* axialShear = nullptr;     // τ_z e_z, when requested
    std::vector<Eigen::Triplet<double>>* circShear = nullptr;      // τ_θ e_θ, when requested
    double zMin = std::numeric_limits<double>::infinity();
    double zMax = -std::numeric_limits<double>::infinity();
    double facetNum = 0.0, facetDen = 0.0;

    template <fem::ElementType T>
    void run();
    // The stages of run, per surface triangle k.
    template <fem::ElementType T>
    TriangleImage<fem::Shape<T>::kNodes> image(std::size_t k);
    /// Faceting: ∫ n_out dA of the curved FE triangle vs the cylinder over the same image.
    template <fem::ElementType T>
    void faceting(const TriangleImage<fem::Shape<T>::kNodes>& im, std::size_t k);
    /// The grid cells overlapped by the image: rows by bisection, columns per periodic shift.
    template <fem::ElementType T>
    void overlappedCells(const TriangleImage<fem::Shape<T>::kNodes>& im);
    /// The load mapping's entries of one piece of the image inside grid cell (i, c) (θ from tc0).
    template <fem::ElementType T>
    void addPiece(const TriangleImage<fem::Shape<T>::kNodes>& im, const Polygon& piece, int i, int c, double tc0);
};

template <fem::ElementType T>
TriangleImage<fem::Shape<T>::kNodes> Setup::image(std::size_t k) {
    constexpr int kN = fem::Shape<T>::kNodes;
    TriangleImage<kN> im;
    const fem::Index t = surf.triangles()[k];
    for (int a = 0; a < kN; ++a) {
        im.node[static_cast<std::size_t>(a)] = mesh.surface.nodes(a, t);
        im.X.col(a) = mesh.nodes.col(mesh.surface.nodes(a, t));
    }
    const auto& X = im.X;
    auto& P = im.P;
    const double ref = std::atan2(X(1, 0), X(0, 0));
    for (int a = 0; a < kN; ++a) {
        double th = std::atan2(X(1, a), X(0, a));
        th += 2.0 * kPi * std::round((ref - th) / (2.0 * kPi));
        P[static_cast<std::size_t>(a)] = Point(X(2, a) - opt.axialOffset, th);
    }
    im.J.col(0) = P[1] - P[0];
    im.J.col(1) = P[2] - P[0];
    im.det = im.J.determinant();
    im.tLo = std::min({P[0](1), P[1](1), P[2](1)});
    im.tHi = std::max({P[0](1), P[1](1), P[2](1)});
    if (im.tHi - im.tLo >= kPi)
        throw std::runtime_error("triangle " + std::to_string(mesh.surface.tags[t]) + " of surface '" + surf.name() +
                                 "' spans half a turn or more");
    if (std::abs(im.det) <= 1e-14 * (im.J.col(0).norm() * im.J.col(1).norm()))
        throw std::invalid_argument("triangle " + std::to_string(mesh.surface.tags[t]) + " of surface '" + surf.name() +
                                    "' has a degenerate (z, θ) image: the surface is not a "
                                    "cylinder about z there");
    im.Jinv = im.J.inverse();
    im.zLo = std::min({P[0](0), P[1](0), P[2](0)});
    im.zHi = std::max({P[0](0), P[1](0), P[2](0)});
    zMin = std::min(zMin, im.zLo);
    zMax = std::max(zMax, im.zHi);
    if constexpr (kN == 6)
        for (int e = 0; e < 3; ++e) {
            const Point mid = 0.5 * (P[static_cast<std::size_t>(fem::kTri6Edges[e][0])] +
                                     P[static_cast<std::size_t>(fem::kTri6Edges[e][1])]);
            const Point d = P[static_cast<std::size_t>(3 + e)] - mid;
            stats.midNodeOffset = std::max(stats.midNodeOffset, std::hypot(d(0), stats.surfaceRadius * d(1)));
        }
    return im;
}

template <fem::ElementType T>
void Setup::faceting(const TriangleImage<fem::Shape<T>::kNodes>& im, std::size_t k) {
    Eigen::Vector3d fe = Eigen::Vector3d::Zero(), cyl = Eigen::Vector3d::Zero();
    const double s = surf.orientation()[k];
    const double sigma = stats.outward;
    double area = 0.0;
    for (const RulePoint& q : rule) {
        const Eigen::Matrix<double, 3, 2> tg = im.X * fem::Shape<T>::dN(Eigen::Vector3d(q.xi, q.eta, 0.0));
        fe += q.weight * s * tg.col(0).cross(tg.col(1));
        const Point x = im.P[0] + im.J * Point(q.xi, q.eta);
        const double w = q.weight * std::abs(im.det) * stats.surfaceRadius;
        cyl += w * sigma * Eigen::Vector3d(std::cos(x(1)), std::sin(x(1)), 0.0);
        area += w;
    }
    facetNum += (fe - cyl).norm();
    facetDen += area;
}

template <fem::ElementType T>
void Setup::overlappedCells(const TriangleImage<fem::Shape<T>::kNodes>& im) {
    const lube::FilmGrid& g = grid;
    const double dTh = g.dTheta();
    const double th0 = g.theta(0);
    const int nz = g.nAxial(), nt = g.nTheta();
    const int nCellsTheta = g.periodic() ? nt : nt - 1;
    const std::vector<double>& zg = g.axial();
    const int iLo = std::max(0, static_cast<int>(std::upper_bound(zg.begin(), zg.end(), im.zLo) - zg.begin()) - 1);
    const int iHi = std::min(nz - 2, static_cast<int>(std::upper_bound(zg.begin(), zg.end(), im.zHi) - zg.begin()) - 1);
    if (iLo > iHi) return;
    const Polygon tri = {im.P[0], im.P[1], im.P[2]};
    // Periodic grids: one shift (cells indexed modulo nθ). Open arcs: the image may sit one
    // turn away from the arc, or straddle its ends when the arc is a full turn.
    const int shiftLo = g.periodic() ? 0 : -1, shiftHi = g.periodic() ? 0 : 1;
    for (int sh = shiftLo; sh <= shiftHi; ++sh) {
        const double off = 2.0 * kPi * sh;
        int cLo = static_cast<int>(std::floor((im.tLo + off - th0) / dTh));
        int cHi = static_cast<int>(std::floor((im.tHi + off - th0) / dTh));
        if (!g.periodic()) {
            cLo = std::max(cLo, 0);
            cHi = std::min(cHi, nCellsTheta - 1);
        }
        for (int i = iLo; i <= iHi; ++i) {
            const double z0 = zg[static_cast<std::size_t>(i)], z1 = zg[static_cast<std::size_t>(i + 1)];
            Polygon strip = clip(clip(tri, 0, z0, true), 0, z1, false);
            if (strip.size() < 3) continue;
            for (int c = cLo; c <= cHi; ++c) {
                // Cell c spans [θ0 + c Δθ, θ0 + (c+1) Δθ] in the image's unwrapped θ − off.
                const double tc0 = th0 + c * dTh - off, tc1 = tc0 + dTh;
                const Polygon piece = clip(clip(strip, 1, tc0, true), 1, tc1, false);
                if (piece.size() < 3) continue;
                const double pieceArea = std::abs(polygonArea(piece));
                if (pieceArea <= 1e-14 * (z1 - z0) * dTh) continue;
                ++stats.fragments;
                stats.coveredArea += g.radius() * pieceArea;
                addPiece<T>(im, piece, i, c, tc0);
            }
        }
    }
}

template <fem::ElementType T>
void Setup::addPiece(const TriangleImage<fem::Shape<T>::kNodes>& im, const Polygon& piece, int i, int c, double tc0) {
    constexpr int kN = fem::Shape<T>::kNodes;
    const lube::FilmGrid& g = grid;
    const double R = g.radius(), dTh = g.dTheta(), sigma = stats.outward;
    const int nt = g.nTheta();
    const double z0 = g.axial()[static_cast<std::size_t>(i)], z1 = g.axial()[static_cast<std::size_t>(i + 1)];
    // block(a, 2 l + d): ∫ N_a φ_l n_d over the piece, φ_l the cell's bilinears,
    // (n_0, n_1) = (cos θ, sin θ); block(a, 8 + l): ∫ N_a φ_l (for τ_z).
    Eigen::Matrix<double, kN, 12> block = Eigen::Matrix<double, kN, 12>::Zero();
    for (std::size_t f = 1; f + 1 < piece.size(); ++f) {
        const Point& A = piece[0];
        const Point e1 = piece[f] - A, e2 = piece[f + 1] - A;
        const double jac = std::abs(e1(0) * e2(1) - e1(1) * e2(0));
        for (const RulePoint& q : rule) {
            const Point x = A + q.xi * e1 + q.eta * e2;
            const Point ref2 = im.Jinv * (x - im.P[0]);
            const auto N = shape<T>(ref2(0), ref2(1));
            const double s = (x(0) - z0) / (z1 - z0), r = (x(1) - tc0) / dTh;
            const double phi[4] = {(1 - s) * (1 - r), (1 - s) * r, s * (1 - r), s * r};
            const double w = q.weight * jac * R;
            const double cs = w * std::cos(x(1)), sn = w * std::sin(x(1));
            for (int l = 0; l < 4; ++l) {
                block.col(2 * l) += (phi[l] * cs) * N;
                block.col(2 * l + 1) += (phi[l] * sn) * N;
                if (axialShear) block.col(8 + l) += (phi[l] * w) * N;
            }
        }
    }
    // Grid nodes of the cell: (i, c), (i, c+1), (i+1, c), (i+1, c+1).
    const int jc0 = ((c % nt) + nt) % nt, jc1 = ((c + 1) % nt + nt) % nt;
    const int cols[4] = {g.index(i, jc0), g.index(i, jc1), g.index(i + 1, jc0), g.index(i + 1, jc1)};
    // F = −∫ p N n_out dA, n_out = σ (cos θ, sin θ, 0).
    for (int a = 0; a < kN; ++a)
        for (int l = 0; l < 4; ++l)
            for (int d = 0; d < 2; ++d)
                triplets.emplace_back(3 * im.node[static_cast<std::size_t>(a)] + d, cols[l], -sigma * block(a, 2 * l + d));
    // Shear: F = ∫ τ_z N e_z dA and F = ∫ τ_θ N (−sin θ, cos θ, 0) dA.
    if (axialShear)
        for (int a = 0; a < kN; ++a)
            for (int l = 0; l < 4; ++l) {
                const int n3 = 3 * im.node[static_cast<std::size_t>(a)];
                axialShear->emplace_back(n3 + 2, cols[l], block(a, 8 + l));
                circShear->emplace_back(n3, cols[l], -block(a, 2 * l + 1));
                circShear->emplace_back(n3 + 1, cols[l], block(a, 2 * l));
            }
}

template <fem::ElementType T>
void Setup::run() {
    facetNum = facetDen = 0.0;
    for (std::size_t k = 0; k < surf.triangles().size(); ++k) {
        const auto im = image<T>(k);
        faceting<T>(im, k);
        overlappedCells<T>(im);
    }
    stats.facetingError = facetDen > 0.0 ? facetNum / facetDen : 0.0;
}

std::string mm(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v * 1e3;
    return s.str();
}

}  // namespace

CylinderSides cylinderSides(const fem::Mesh& mesh, const fem::BoundarySurface& surf) {
    CylinderSides sides;
    for (std::size_t k = 0; k < surf.triangles().size(); ++k) {
        const fem::Index t = surf.triangles()[k];
        const Eigen::Vector3d x0 = mesh.nodes.col(mesh.surface.nodes(0, t));
        const Eigen::Vector3d x1 = mesh.nodes.col(mesh.surface.nodes(1, t));
        const Eigen::Vector3d x2 = mesh.nodes.col(mesh.surface.nodes(2, t));
        const Eigen::Vector3d c = (x0 + x1 + x2) / 3.0;
        const double dot = surf.orientation()[k] * (x1 - x0).cross(x2 - x0).dot(Eigen::Vector3d(c(0), c(1), 0.0));
        (dot > 0.0 ? sides.away : sides.towards) += 1;
    }
    return sides;
}

LoadMapping::LoadMapping(const fem::Mesh& mesh, const std::string& surface,
                         const lube::FilmGrid& grid, const LoadMappingOptions& options)
    : surface_(surface) {
    const fem::BoundarySurface surf(mesh, surface);
    if (surf.triangles().empty())
        throw std::invalid_argument("surface '" + surface + "' has no triangles");

    // Cylindricity: radii of all surface nodes (vertices and mid-nodes).
    double rMin = std::numeric_limits<double>::infinity(), rMax = 0.0, rSum = 0.0;
    const std::vector<fem::Index> nodes = mesh.groupNodes(surface);
    for (fem::Index n : nodes) {
        const double r = mesh.nodes.col(n).head<2>().norm();
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
        rSum += r;
    }
    stats_.surfaceRadius = rSum / static_cast<double>(nodes.size());
    stats_.radiusSpread = (rMax - rMin) / stats_.surfaceRadius;
    if (!(stats_.radiusSpread <= options.radiusTolerance))
        throw std::invalid_argument(
            "surface '" + surface + "' is not a cylinder about z: node radii from " + mm(rMin) + " to " + mm(rMax) +
            " mm (relative spread " + std::to_string(stats_.radiusSpread) + " > tolerance " +
            std::to_string(options.radiusTolerance) + ")");

    // Which side of the cylinder the body lies on, from the outward normals of the triangles.
    const CylinderSides sides = cylinderSides(mesh, surf);
    const int inside = sides.away, outside = sides.towards;
    if (inside > 0 && outside > 0)
        throw std::invalid_argument("surface '" + surface + "' faces the axis on " + std::to_string(outside) +
                                    " triangles and away from it on " + std::to_string(inside) +
                                    "; one side of a cylinder is needed");
    stats_.outward = inside > 0 ? 1.0 : -1.0;

    stats_.gridArea = grid.radius() * grid.length() * grid.angularExtent();
    stats_.quadratureOrder = ruleOrder(grid.dTheta());
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<Eigen::Triplet<double>> tz, tt;
    Setup s{mesh, surf, grid, options, stats_, triplets, collapsedRule(stats_.quadratureOrder)};
    if (options.shear) {
        s.axialShear = &tz;
        s.circShear = &tt;
    }
    if (mesh.surface.type == fem::ElementType::Tri3)
        s.run<fem::ElementType::Tri3>();
    else
        s.run<fem::ElementType::Tri6>();
    if (stats_.fragments == 0) {
        std::ostringstream m;
        m.precision(4);
        m << "the film grid (z from " << grid.axial().front() * 1e3 << " to "
          << grid.axial().back() * 1e3 << " mm, axial offset " << options.axialOffset * 1e3
          << " mm; θ from " << grid.theta(0) << " rad over " << grid.angularExtent()
          << " rad) does not overlap surface '" << surface << "' (z from " << (s.zMin + options.axialOffset) * 1e3 << " to "
          << (s.zMax + options.axialOffset) * 1e3 << " mm)";
        throw std::invalid_argument(m.str());
    }
    A_.resize(3 * mesh.numNodes(), grid.size());
    A_.setFromTriplets(triplets.begin(), triplets.end());
    A_.makeCompressed();
    if (options.shear) {
        Sz_.resize(A_.rows(), A_.cols());
        Sz_.setFromTriplets(tz.begin(), tz.end());
        Sz_.makeCompressed();
        St_.resize(A_.rows(), A_.cols());
        St_.setFromTriplets(tt.begin(), tt.end());
        St_.makeCompressed();
    }
}

Eigen::VectorXd LoadMapping::apply(const Eigen::VectorXd& p) const {
    Eigen::VectorXd f;
    apply(p, f);
    return f;
}

void LoadMapping::apply(const Eigen::VectorXd& p, Eigen::VectorXd& forces) const {
    if (p.size() != A_.cols())
        throw std::invalid_argument("LoadMapping::apply: " + std::to_string(p.size()) +
                                    " pressures for a grid of " + std::to_string(A_.cols()) + " nodes");
    forces.noalias() = A_ * p;
}

Eigen::VectorXd LoadMapping::applyShear(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta) const {
    if (Sz_.size() == 0)
        throw std::logic_error("LoadMapping::applyShear: built without the shear operators (options.shear)");
    for (const Eigen::VectorXd* t : {&tauZ, &tauTheta})
        if (t->size() != 0 && t->size() != A_.cols())
            throw std::invalid_argument("LoadMapping::applyShear: " + std::to_string(t->size()) +
                                        " tractions for a grid of " + std::to_string(A_.cols()) + " nodes");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(A_.rows());
    if (tauZ.size() != 0) f.noalias() += Sz_ * tauZ;
    if (tauTheta.size() != 0) f.noalias() += St_ * tauTheta;
    return f;
}

}  // namespace flexehd::cosim
