#include "lube/FilmIntegrals.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "lube/FilmNodeGeometry.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "lube/ShearStressFactor.hpp"

namespace flexehd::lube {

namespace {

void checkField(const FilmGrid& g, const Eigen::VectorXd* v, const char* what) {
    if (v && v->size() != g.size())
        throw std::invalid_argument(std::string("integrateFilm: ") + what + " has " +
                                    std::to_string(v->size()) + " values, grid has " +
                                    std::to_string(g.size()));
}

Eigen::VectorXd nodalViscosity(const FilmGrid& g, const Lubricant& lub, const Eigen::VectorXd& p) {
    Eigen::VectorXd eta(g.size());
    for (int k = 0; k < g.size(); ++k) eta[k] = lub.viscosity(p[k] - g.ambientPressure());
    return eta;
}

double faceFlow(const FilmGrid& g, const FilmState& film, const Eigen::VectorXd& eta,
                const Eigen::VectorXd& p, const Eigen::VectorXd* phi, int a, int b, bool axial,
                double L, double d) {
    const double hf = faceValue(g, film.h, a, b);
    const double ef = faceValue(g, eta, a, b);
    const double U = axial ? film.sumAxial() : film.sumCircumferential();
    // The film fraction the Couette flow carries: the upstream node's, as in the mass-conserving
    // scheme (JfoSolver), so that the flows balance as its equations do (a face from a Void node:
    // the face value, the film's own).
    const int up = U > 0.0 ? a : b;
    const double frac = !phi ? 1.0 : g.kind(up) == NodeKind::Void ? faceValue(g, *phi, a, b) : (*phi)[up];
    return hf * hf * hf * L / (12.0 * ef * d) * (p[a] - p[b]) + 0.5 * U * frac * hf * L;
}

}  // namespace

FilmLoads integrateFilm(const FilmGrid& g, const FilmState& film, const Lubricant& lub,
                        const Eigen::VectorXd& p, const FilmIntegralOptions& opt) {
    validateFilmState(g, film);
    if (p.size() != g.size())
        throw std::invalid_argument("integrateFilm: pressure has " + std::to_string(p.size()) +
                                    " values, grid has " + std::to_string(g.size()));
    checkField(g, opt.contactPressure, "contact pressure");
    checkField(g, opt.filmFraction, "film fraction");
    const int nz = g.nAxial(), nt = g.nTheta();
    const double pAmb = g.ambientPressure();
    const Eigen::VectorXd eta = nodalViscosity(g, lub, p);
    const double dVz = film.outer.axial - film.inner.axial;
    const double dVt = film.outer.circumferential - film.inner.circumferential;
    const double dV = std::hypot(dVz, dVt);
    const ShearStressFactor shearFactor(opt.roughness);

    FilmLoads out;
    out.minFilm = std::numeric_limits<double>::infinity();
    out.maxPressure = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < nz; ++i) {
        for (int j = 0; j < nt; ++j) {
            const int k = g.index(i, j);
            if (g.kind(k) == NodeKind::Void) continue;
            const NodeFrame f = nodeFrame(g, i, j);
            const double A = f.area, S = f.surfaceArea;  // pressure; everything else (arc ends)
            const Eigen::Vector3d &er = f.er, &et = f.et, &ez = f.ez, &r = f.position;
            const double h = film.h[k];
            // ∇p: ∂p/∂z and (1/R) ∂p/∂θ.
            const double dpdz = axialStencil(g, i, j).apply(p), dpdy = circumferentialStencil(g, i, j).apply(p);

            const double phi = opt.filmFraction ? (*opt.filmFraction)[k] : 1.0;
            double c, dcdh;
            shearFactor.couette(h, c, dcdh);
            const double couette = phi * eta[k] * c;
            const double tz = couette * dVz - 0.5 * h * dpdz;
            const double tt = couette * dVt - 0.5 * h * dpdy;
            const double pc = opt.contactPressure ? (*opt.contactPressure)[k] : 0.0;

            const Eigen::Vector3d fp = -(p[k] - pAmb) * A * er;
            const Eigen::Vector3d fc = -pc * S * er;
            const Eigen::Vector3d fs = (tz * ez + tt * et) * S;
            const Eigen::Vector3d fo = (-(couette * dVz + 0.5 * h * dpdz) * ez - (couette * dVt + 0.5 * h * dpdy) * et) * S;
            Eigen::Vector3d fb = Eigen::Vector3d::Zero();
            if (dV > 0.0) fb = opt.boundaryFriction * pc * S / dV * (dVz * ez + dVt * et);
            out.pressureForce += fp;
            out.contactForce += fc;
            out.shearForce += fs;
            out.outerShearForce += fo;
            out.boundaryFrictionForce += fb;
            out.moment += (r - opt.referencePoint).cross(fp + fc + fs + fb);
            out.viscousDissipation +=
                (couette * dV * dV + h * h * h * (axialDerivativeSquared(g, i, j, p) +
                                                  circumferentialDerivativeSquared(g, i, j, p)) /
                                         (12.0 * eta[k])) * S;
            out.boundaryFrictionPower += opt.boundaryFriction * pc * dV * S;
            out.contactLoad += pc * S;
            out.minFilm = std::min(out.minFilm, h);
            out.maxPressure = std::max(out.maxPressure, p[k]);
            out.filmArea += S;
            if (g.kind(k) == NodeKind::Film && p[k] <= opt.cavitationPressure)
                out.cavitatedArea += S;
        }
    }
    if (!out.pressureForce.allFinite() || !out.shearForce.allFinite() || !out.moment.allFinite())
        throw std::runtime_error("integrateFilm: non-finite load (check pressure and contact "
                                 "fields for NaN)");
    return out;
}

double circumferentialFlow(const FilmGrid& g, const FilmState& film, const Lubricant& lub,
                           const Eigen::VectorXd& p, int j, const Eigen::VectorXd* phi) {
    validateFilmState(g, film);
    const int nt = g.nTheta();
    if (j < 0 || j >= nt || (!g.periodic() && j == nt - 1))
        throw std::out_of_range("circumferentialFlow: column " + std::to_string(j) +
                                " has no face towards +theta");
    const Eigen::VectorXd eta = nodalViscosity(g, lub, p);
    double q = 0.0;
    for (int i = 0; i < g.nAxial(); ++i) {
        const int a = g.index(i, j), b = g.index(i, (j + 1) % nt);
        if (g.kind(a) == NodeKind::Void && g.kind(b) == NodeKind::Void) continue;
        q += faceFlow(g, film, eta, p, phi, a, b, false, g.axialWidth(i), g.radius() * g.faceAngle(j));
    }
    return q;
}

double axialFlow(const FilmGrid& g, const FilmState& film, const Lubricant& lub,
                 const Eigen::VectorXd& p, int i, const Eigen::VectorXd* phi) {
    validateFilmState(g, film);
    if (i < 0 || i >= g.nAxial() - 1)
        throw std::out_of_range("axialFlow: row " + std::to_string(i) + " has no face towards +z");
    const Eigen::VectorXd eta = nodalViscosity(g, lub, p);
    double q = 0.0;
    for (int j = 0; j < g.nTheta(); ++j) {
        const int a = g.index(i, j), b = g.index(i + 1, j);
        if (g.kind(a) == NodeKind::Void && g.kind(b) == NodeKind::Void) continue;
        q += faceFlow(g, film, eta, p, phi, a, b, true, g.radius() * g.angularWidth(j),
                      g.z(i + 1) - g.z(i));
    }
    return q;
}

double axialEdgeFlow(const FilmGrid& g, const FilmState& film, const Lubricant& lub, const Eigen::VectorXd& p,
                     Edge edge, const Eigen::VectorXd* phi) {
    validateFilmState(g, film);
    const int nz = g.nAxial();
    if (nz < 3) throw std::invalid_argument("axialEdgeFlow: the grid needs at least 3 rows");
    if (edge != Edge::AxialLow && edge != Edge::AxialHigh)
        throw std::invalid_argument("axialEdgeFlow: an axial edge (AxialLow or AxialHigh) is needed");
    const Eigen::VectorXd eta = nodalViscosity(g, lub, p);
    const bool low = edge == Edge::AxialLow;
    // Rows of the edge and of the first two faces inside it (face f between rows f and f + 1).
    const int r0 = low ? 0 : nz - 1, f0 = low ? 0 : nz - 2, f1 = low ? 1 : nz - 3;
    auto mid = [&](int f) { return 0.5 * (g.z(f) + g.z(f + 1)); };
    const double w = (mid(f0) - g.z(r0)) / (mid(f1) - mid(f0));  // extrapolation weight
    double q = 0.0;
    for (int j = 0; j < g.nTheta(); ++j) {
        const double L = g.radius() * g.angularWidth(j);
        auto flux = [&](int f) {
            const int a = g.index(f, j), b = g.index(f + 1, j);
            if (g.kind(a) == NodeKind::Void && g.kind(b) == NodeKind::Void) return 0.0;
            return faceFlow(g, film, eta, p, phi, a, b, true, L, g.z(f + 1) - g.z(f));
        };
        const double q0 = flux(f0), q1 = flux(f1);
        q += q0 + (q0 - q1) * w;
    }
    return q;
}

}  // namespace flexehd::lube
