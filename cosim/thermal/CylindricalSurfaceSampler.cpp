#include "cosim/thermal/CylindricalSurfaceSampler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/LU>

#include "fem/ShapeFunctions.hpp"

namespace flexehd::cosim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Barycentric coordinates (L1, L2) of p in triangle (a, b, c): p = a + L1 (b − a) + L2 (c − a).
Eigen::Vector2d barycentric(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                            const Eigen::Vector2d& c) {
    Eigen::Matrix2d M;
    M.col(0) = b - a;
    M.col(1) = c - a;
    return M.inverse() * (p - a);
}

/// Closest point of triangle (a, b, c) to p, as barycentrics (L1, L2), and its distance.
Eigen::Vector2d closestBarycentric(const Eigen::Vector2d& p, const Eigen::Vector2d v[3], double& dist) {
    const Eigen::Vector2d L = barycentric(p, v[0], v[1], v[2]);
    if (L.minCoeff() >= 0.0 && L.sum() <= 1.0) {
        dist = 0.0;
        return L;
    }
    // Nearest point on the three edges.
    dist = 1e300;
    Eigen::Vector2d best(0, 0);
    for (int e = 0; e < 3; ++e) {
        const Eigen::Vector2d& a = v[e];
        const Eigen::Vector2d& b = v[(e + 1) % 3];
        const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
        const double d = (a + t * (b - a) - p).norm();
        if (d < dist) {
            dist = d;
            Eigen::Vector3d l = Eigen::Vector3d::Zero();  // (L0, L1, L2)
            l(e) = 1.0 - t;
            l((e + 1) % 3) = t;
            best = l.tail<2>();
        }
    }
    return best;
}

}  // namespace

CylindricalSurfaceSampler::CylindricalSurfaceSampler(const fem::Mesh& mesh, const std::vector<std::string>& groups)
    : mesh_(mesh) {
    std::vector<fem::Index> elements;
    for (const auto& g : groups) {
        const fem::PhysicalGroup& pg = mesh.group(g);  // unknown: invalid_argument listing the groups
        if (pg.dim != 2)
            throw std::invalid_argument("group '" + g + "' of mesh '" + mesh.source + "' is not a surface");
        elements.insert(elements.end(), pg.elements.begin(), pg.elements.end());
    }
    if (elements.empty()) throw std::invalid_argument("surface groups of mesh '" + mesh.source + "' are empty");
    double rSum = 0.0;
    int count = 0;
    zMin_ = 1e300, zMax_ = -1e300;
    for (fem::Index t : elements)
        for (int a = 0; a < mesh.surface.nodes.rows(); ++a) {
            const Eigen::Vector3d x = mesh.nodes.col(mesh.surface.nodes(a, t));
            rSum += x.head<2>().norm(), ++count;
            zMin_ = std::min(zMin_, x(2)), zMax_ = std::max(zMax_, x(2));
        }
    radius_ = rSum / count;
    for (fem::Index t : elements) {
        Triangle tri;
        tri.element = t;
        double th[3];
        for (int a = 0; a < 3; ++a) {
            const Eigen::Vector3d x = mesh.nodes.col(mesh.surface.nodes(a, t));
            th[a] = std::atan2(x(1), x(0));
        }
        // Unwrap: keep the vertices within π of the first one.
        for (int a = 1; a < 3; ++a) {
            if (th[a] - th[0] > std::numbers::pi) th[a] -= kTwoPi;
            if (th[a] - th[0] < -std::numbers::pi) th[a] += kTwoPi;
        }
        for (int a = 0; a < 3; ++a) tri.p[a] = {mesh.nodes(2, mesh.surface.nodes(a, t)), radius_ * th[a]};
        tri.lo = tri.p[0].cwiseMin(tri.p[1]).cwiseMin(tri.p[2]);
        tri.hi = tri.p[0].cwiseMax(tri.p[1]).cwiseMax(tri.p[2]);
        triangles_.push_back(tri);
    }
}

void CylindricalSurfaceSampler::checkSize(int nAxial, int nTheta) const {
    if (nAxial < 2 || nTheta < 3) throw std::invalid_argument("surface table needs n_z >= 2 and n_theta >= 3");
}

CylindricalSurfaceSampler::Location CylindricalSurfaceSampler::locate(double z, double th) const {
    const double period = kTwoPi * radius_;
    const double tol = 1e-10 * std::max(period, zMax_ - zMin_);
    const double s0 = radius_ * (th > std::numbers::pi ? th - kTwoPi : th);  // in (−πR̄, πR̄]
    double bestDist = 1e300;
    Location out;
    Eigen::Vector2d bestL(0, 0);
    for (const Triangle& tri : triangles_)
        for (double shift : {0.0, period, -period}) {
            const Eigen::Vector2d p(z, s0 + shift);
            // Lower bound of the distance by the bounding box: skip far triangles.
            const Eigen::Vector2d gap = (tri.lo - p).cwiseMax(p - tri.hi).cwiseMax(0.0);
            if (gap.norm() >= bestDist) continue;
            double d = 0.0;
            const Eigen::Vector2d L = closestBarycentric(p, tri.p, d);
            if (d < bestDist) bestDist = d, out.triangle = &tri, bestL = L;
        }
    // Shape functions of the triangle at (ξ, η) = (L1, L2), Gmsh order.
    const Eigen::Vector3d xi(bestL(0), bestL(1), 0.0);
    if (mesh_.surface.type == fem::ElementType::Tri6) out.N = fem::Shape<fem::ElementType::Tri6>::N(xi);
    else out.N = fem::Shape<fem::ElementType::Tri3>::N(xi);
    out.onSurface = bestDist <= tol;
    return out;
}

SurfaceTable CylindricalSurfaceSampler::sample(const Eigen::VectorXd& u, int nAxial, int nTheta) const {
    checkSize(nAxial, nTheta);
    if (u.size() != 3 * mesh_.numNodes())
        throw std::invalid_argument("surface table: displacement has " + std::to_string(u.size()) +
                                    " values, expected 3 x " + std::to_string(mesh_.numNodes()));
    SurfaceTable out;
    out.meanRadius = radius_;
    out.radial.resize(nAxial, nTheta);
    out.onSurface.resize(nAxial, nTheta);
    for (int i = 0; i < nAxial; ++i) out.axial.push_back(zMin_ + (zMax_ - zMin_) * i / (nAxial - 1));
    for (int j = 0; j < nTheta; ++j) out.theta.push_back(kTwoPi * j / nTheta);
    for (int i = 0; i < nAxial; ++i)
        for (int j = 0; j < nTheta; ++j) {
            const double th = out.theta[std::size_t(j)];
            const Location at = locate(out.axial[std::size_t(i)], th);
            Eigen::Vector3d disp = Eigen::Vector3d::Zero();
            for (int a = 0; a < at.N.size(); ++a)
                disp += at.N(a) * u.segment<3>(3 * mesh_.surface.nodes(a, at.triangle->element));
            out.radial(i, j) = disp(0) * std::cos(th) + disp(1) * std::sin(th);
            out.onSurface(i, j) = at.onSurface ? 1 : 0;
        }
    return out;
}

ScalarSurfaceTable CylindricalSurfaceSampler::sampleScalar(const Eigen::VectorXd& nodal, int nAxial,
                                                           int nTheta) const {
    checkSize(nAxial, nTheta);
    if (nodal.size() != mesh_.numNodes())
        throw std::invalid_argument("surface table: nodal field has " + std::to_string(nodal.size()) +
                                    " values, expected " + std::to_string(mesh_.numNodes()));
    ScalarSurfaceTable out;
    out.values.resize(nAxial, nTheta);
    out.onSurface.resize(nAxial, nTheta);
    for (int i = 0; i < nAxial; ++i) out.axial.push_back(zMin_ + (zMax_ - zMin_) * i / (nAxial - 1));
    for (int j = 0; j < nTheta; ++j) out.theta.push_back(kTwoPi * j / nTheta);
    for (int i = 0; i < nAxial; ++i)
        for (int j = 0; j < nTheta; ++j) {
            const Location at = locate(out.axial[std::size_t(i)], out.theta[std::size_t(j)]);
            double v = 0.0;
            for (int a = 0; a < at.N.size(); ++a) v += at.N(a) * nodal(mesh_.surface.nodes(a, at.triangle->element));
            out.values(i, j) = v;
            out.onSurface(i, j) = at.onSurface ? 1 : 0;
        }
    return out;
}

AxialProfile axialProfile(const ScalarSurfaceTable& t) {
    AxialProfile p;
    p.axial = t.axial;
    for (Eigen::Index i = 0; i < t.values.rows(); ++i) {
        double on = 0.0, all = 0.0;
        int nOn = 0;
        for (Eigen::Index j = 0; j < t.values.cols(); ++j) {
            all += t.values(i, j);
            if (t.onSurface(i, j)) on += t.values(i, j), ++nOn;
        }
        p.values.push_back(nOn > 0 ? on / nOn : all / double(t.values.cols()));
    }
    return p;
}

}  // namespace flexehd::cosim
