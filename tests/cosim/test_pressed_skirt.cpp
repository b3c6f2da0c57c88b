// A flexible skirt pressed into the liner by a known force settles at the gap the static
// finite-element solution gives (docs/coupling.md §2, hard contact with a flexible piston).
//
// The small flexible piston (8 modes + skirt static correction, pin bore held) runs in
// flexehd run's master at 0.1 rpm under a constant cylinder pressure of 40 bar with a thin
// oil (1e-4 Pa·s): inertia and the film's hydrodynamic pressure vanish, the connecting rod's side force (a known function of the gas
// force and the crank angle) presses the thrust side of the skirt into the liner and the
// asperity and coating (hard) contact carry it. The reference solves the same static contact
// problem on the full finite-element model of the same mesh: the skirt's radial compliance
// G = −D K⁻¹ A (pin bore fixed; one static solve per film node), the same contact laws and
// the same force and moment balance of PistonDynamics, Newton on the film thickness inside
// Newton on (e, β). The master must settle exactly at the static solution of its own reduced
// body (shift, tilt and true minimum gap, an interference), and that within the Ritz error at
// the full model's shift and tilt; the rigid skirt's solution of the same problem is far from
// both, so the test sees whether the body's compliance takes part.
#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/LoadMapping.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/StaticSolver.hpp"
#include "lube/FilmIntegrals.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

// The grid nodes that carry film (not Void).
std::vector<int> filmCarryingNodes(const lube::FilmGrid& g) {
    std::vector<int> nodes;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) nodes.push_back(k);
    return nodes;
}

// The static contact problem of the skirt at one crank state: film thickness
//     h = h_rigid(e, β) + G p_c(h)
// with p_c = Greenwood–Tripp asperity pressure + coating foundation, and the piston's
// equations of motion without inertia: PistonDynamics::force(crank, gas, contact action) = 0.
class StaticContactProblem {
public:
    StaticContactProblem(const EngineCase& c, const PistonSimulation& sim, Eigen::MatrixXd G)
        : c_(c), sim_(sim), G_(std::move(G)),
          asperity_(c.contact.sigma, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus),
          foundation_(lube::ElasticFoundation::layerStiffness(c.contact.coatingModulus, c.contact.coatingPoisson,
                                                              c.contact.coatingThickness)),
          lubricant_(c.lubricant.viscosity, c.lubricant.density) {
        film_ = filmCarryingNodes(sim.contact<SkirtContact>().film().grid());
    }

    // (e, β) where the contact balances the rod and gas forces at the crank angle.
    Eigen::Vector2d solve(double crankDeg, double gas, Eigen::Vector2d x) {
        const CrankState crank = sim_.kinematics().at(crankDeg);
        for (int it = 0; it < 40; ++it) {
            const Eigen::Vector2d r = residual(crank, gas, x);
            Eigen::Matrix2d J;
            const Eigen::Vector2d dx(1e-9, 1e-7);
            for (int j = 0; j < 2; ++j) {
                Eigen::Vector2d xp = x;
                xp[j] += dx[j];
                J.col(j) = (residual(crank, gas, xp) - r) / dx[j];
            }
            const Eigen::Vector2d step = J.partialPivLu().solve(-r);
            x += step;
            if (std::abs(step[0]) < 1e-12 && std::abs(step[1]) < 1e-10) {
                residual(crank, gas, x);  // the minimum gap of the solution
                return x;
            }
        }
        ADD_FAILURE() << "the reference contact solution did not converge";
        return x;
    }

    double minGap() const { return minGap_; }
    int filmNodes() const { return int(film_.size()); }

private:
    Eigen::Vector2d residual(const CrankState& crank, double gas, const Eigen::Vector2d& x) {
        const lube::FilmGrid& g = sim_.contact<SkirtContact>().film().grid();
        Eigen::VectorXd hRigid;
        sim_.contact<SkirtContact>().film().rigidThickness(x[0], x[1], hRigid);
        Eigen::VectorXd h = filmThickness(hRigid);
        Eigen::VectorXd pc = Eigen::VectorXd::Zero(g.size());
        minGap_ = std::numeric_limits<double>::infinity();
        for (const int k : film_) {
            pc[k] = pressure(h[k]);
            minGap_ = std::min(minGap_, h[k]);
            h[k] = std::max(h[k], 0.05 * c_.contact.sigma);  // the fluid film the master's Reynolds solve sees
        }
        lube::FilmState fs;
        fs.h = h;
        fs.dhdt = Eigen::VectorXd::Zero(g.size());
        fs.outer.axial = -crank.velocity;
        lube::FilmIntegralOptions io;
        io.referencePoint = Eigen::Vector3d(c_.engine.pinOffset, 0.0, 0.0);
        io.boundaryFriction = c_.contact.boundaryFriction;
        io.contactPressure = &pc;
        const lube::FilmLoads loads = lube::integrateFilm(g, fs, lubricant_, Eigen::VectorXd::Zero(g.size()), io);
        const Eigen::Vector3d F = loads.totalForce();
        return sim_.dynamics().force(crank, gas, {F.x(), F.z(), loads.moment.y()});
    }

    // h = h_rigid + G p_c(h) on the film nodes, Newton with backtracking from h_rigid.
    Eigen::VectorXd filmThickness(const Eigen::VectorXd& hRigid) const {
        const int n = int(film_.size());
        Eigen::VectorXd h(n), hr(n);
        for (int i = 0; i < n; ++i) h[i] = hr[i] = hRigid[film_[i]];
        auto residual = [&](const Eigen::VectorXd& v) {
            Eigen::VectorXd p(n);
            for (int i = 0; i < n; ++i) p[i] = pressure(v[i]);
            return Eigen::VectorXd(v - hr - G_ * p);
        };
        Eigen::VectorXd R = residual(h);
        for (int it = 0; it < 100 && R.cwiseAbs().maxCoeff() > 1e-13; ++it) {
            Eigen::MatrixXd J = -G_;
            for (int i = 0; i < n; ++i) J.col(i) *= slope(h[i]);
            J.diagonal().array() += 1.0;
            const Eigen::VectorXd step = J.partialPivLu().solve(-R);
            double t = 1.0;
            for (; t > 1e-4; t *= 0.5) {
                const Eigen::VectorXd Rt = residual(h + t * step);
                if (Rt.norm() < R.norm()) {
                    h += t * step;
                    R = Rt;
                    break;
                }
            }
            if (t <= 1e-4) break;
        }
        Eigen::VectorXd full = hRigid;
        for (int i = 0; i < n; ++i) full[film_[i]] = h[i];
        return full;
    }

    double pressure(double h) const { return asperity_.pressure(std::max(h, 0.0)) + foundation_.pressure(h); }
    double slope(double h) const { return h < 0.0 ? foundation_.pressureSlope(h) : asperity_.pressureSlope(h); }

    const EngineCase& c_;
    const PistonSimulation& sim_;
    Eigen::MatrixXd G_;  // film nodes × film nodes, m/Pa
    lube::GreenwoodTripp asperity_;
    lube::ElasticFoundation foundation_;
    lube::Lubricant lubricant_;
    std::vector<int> film_;
    double minGap_ = 0.0;
};

// G = −D K⁻¹ A on the film nodes of the piston grid: the full finite-element model of the
// reduced body's mesh and material with the pin bore fixed (the held RBE2 interface).
Eigen::MatrixXd fullModelCompliance(const FlexibleSurface& piston, const lube::FilmGrid& g) {
    const modal::ReducedBody& body = piston.body();
    const LoadMapping load(body.mesh, piston.surface(), g);
    const DeformationMapping def(body.mesh, piston.surface(), g);
    const fem::SparseMatrix K = fem::ElasticityAssembler(body.mesh).stiffness(body.material);
    fem::DofMap dofs(body.mesh.numNodes(), 3);
    dofs.constrain(body.mesh.groupNodes("pin_bore"), fem::kAllComponents);
    dofs.finalize();
    const fem::StaticSolver solver(dofs.reduce(K));
    const std::vector<int> film = filmCarryingNodes(g);
    Eigen::MatrixXd G(film.size(), film.size());
    for (std::size_t j = 0; j < film.size(); ++j) {
        const Eigen::VectorXd f = load.matrix().col(film[j]);
        const Eigen::VectorXd u = dofs.expand(solver.solve(dofs.reduceLoad(f, K)));
        const Eigen::VectorXd ur = def.radial() * u;
        for (std::size_t i = 0; i < film.size(); ++i) G(i, j) = -ur[film[i]];
    }
    return G;
}

// The same with the reduced body as the master uses it (FlexibleSurface: C Φᵀ A, D Φ).
Eigen::MatrixXd reducedCompliance(const FlexibleSurface& piston, const lube::FilmGrid& g) {
    const std::vector<int> film = filmCarryingNodes(g);
    Eigen::MatrixXd G(film.size(), film.size());
    Eigen::VectorXd p = Eigen::VectorXd::Zero(g.size()), f, q, dh;
    for (std::size_t j = 0; j < film.size(); ++j) {
        p[film[j]] = 1.0;
        piston.modalForce(p, 0.0, f);
        piston.quasiStatic(f, q);
        piston.filmChange(q, 0.0, dh);
        p[film[j]] = 0.0;
        for (std::size_t i = 0; i < film.size(); ++i) G(i, j) = dh[film[i]];
    }
    return G;
}

}  // namespace

TEST(PressedSkirt, SettlesAtTheGapOfTheStaticFiniteElementSolution) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("flexehd_press_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    // The small piston's mesh with the skirt static correction of tests/cosim/test_modal_mapping.cpp
    // (axial order 4, circumferential order 6: within 1 % of the full model for skirt loads).
    const auto red = test::runFlexehd("reduce --mesh " + std::string(FLEXEHD_SOURCE_DIR) +
                                      "/meshes/piston.geo --size 0.0065 --E 7.5e10 --nu 0.33 --rho 2700 "
                                      "--interface pin_bore:rbe2@0,0,0 --modes 8 --static-correction skirt "
                                      "--axial-order 4 --circumferential-order 6 --out " + file);
    ASSERT_EQ(red.status, 0) << red.err;

    EngineCase c = test::smallFlexibleCase(file);
    c.engine.speedRpm = 0.1;
    c.time.minStepDeg = 1e-7;  // the free flight into contact at the start takes 0.16 ms = 1e-4°
    c.contact.boundaryFriction = 0.0;
    c.lubricant.viscosity = 1e-4;  // Pa·s: with 0.1 rpm the film carries < 1e-4 of the side force
    const double cylinder = 40e5;  // Pa, absolute, constant: gas force 22.7 kN, side force 7.1 kN at 90°
    c.cylinderPressure.clear();
    for (int d = 0; d <= 720; d += 10) c.cylinderPressure.push_back({double(d), cylinder});
    c.time.startDeg = 60.0;
    PistonSimulation sim(c);
    const std::vector<StepRecord> steps = sim.run({}, 30.0);
    ASSERT_FALSE(steps.empty());
    const StepRecord& r = steps.back();
    std::printf("  master at %.2f deg: side force %.1f N, film %.3g N, contact %.1f N (hard %.1f N), e %.3f um, "
                "beta %.4f mrad, min gap %.4f um\n",
                r.crankDeg, r.sideForce, r.filmForce, r.contactForce, r.hardContactForce, 1e6 * r.lateral,
                1e3 * r.tilt, 1e6 * r.minFilm);
    // The press is static: the hydrodynamic film carries nothing of the side force.
    ASSERT_GT(std::abs(r.sideForce), 1000.0);
    ASSERT_LT(std::abs(r.filmForce), 1e-3 * std::abs(r.sideForce));

    const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();
    const double gas = sim.dynamics().gasForce(cylinder);
    const Eigen::Vector2d start(r.lateral, r.tilt);
    StaticContactProblem full(c, sim, fullModelCompliance(*sim.contact<SkirtContact>().piston(), g));
    const Eigen::Vector2d xf = full.solve(r.crankDeg, gas, start);
    StaticContactProblem reduced(c, sim, reducedCompliance(*sim.contact<SkirtContact>().piston(), g));
    const Eigen::Vector2d xm = reduced.solve(r.crankDeg, gas, start);
    StaticContactProblem rigid(c, sim, Eigen::MatrixXd::Zero(full.filmNodes(), full.filmNodes()));
    const Eigen::Vector2d xr = rigid.solve(r.crankDeg, gas, start);
    std::printf("  static solution, full FE: e %.3f um, beta %.4f mrad, min gap %.4f um\n"
                "  static solution, reduced body: e %.3f um, beta %.4f mrad, min gap %.4f um\n"
                "  static solution, rigid skirt: e %.3f um, beta %.4f mrad, min gap %.4f um\n",
                1e6 * xf[0], 1e3 * xf[1], 1e6 * full.minGap(), 1e6 * xm[0], 1e3 * xm[1], 1e6 * reduced.minGap(),
                1e6 * xr[0], 1e3 * xr[1], 1e6 * rigid.minGap());
    // The skirt's compliance moves the pin axis by e_flexible − e_rigid.
    const double elastic = std::abs(xf[0] - xr[0]);
    ASSERT_GT(elastic, 5e-6) << "the press must deform the skirt for the test to see its compliance";
    // 1. The master settles at the static solution of its own model (reduced body, same laws):
    //    the step's equations are solved to 1e-5 c_r, the film and inertia are negligible.
    EXPECT_NEAR(r.lateral, xm[0], 0.005 * elastic);
    EXPECT_NEAR(r.tilt, xm[1], 0.01 * std::abs(xm[1]));
    EXPECT_NEAR(r.minFilm, reduced.minGap(), 0.02 * std::abs(reduced.minGap()) + 1e-9);
    // 2. That model is the full finite-element model's within the Ritz error of 8 modes with the
    //    skirt static correction (≤ 2 % for skirt loads, tests/modal/test_craig_bampton.cpp;
    //    a reduced model is stiffer: its elastic shift is smaller, never larger), and the rigid
    //    skirt is far from both. The interference (a few tens of nm against 0.24 µm for the
    //    rigid skirt) follows the contact area and is not compared with the full model.
    EXPECT_LT(std::abs(xm[0] - xf[0]), 0.03 * elastic);
    EXPECT_LE(std::abs(xm[0] - xr[0]), elastic * (1 + 1e-9));
    EXPECT_LT(std::abs(r.lateral - xf[0]), 0.03 * elastic);
    EXPECT_LT(std::abs(r.tilt - xf[1]), 0.05 * std::abs(xf[1]));
    EXPECT_GT(r.hardContactForce * r.contactForce, 0.0) << "the press must reach the hard contact";
    EXPECT_LT(r.minFilm, 0.0);
    // 3. A second surface in front of the same body (its compliance shared, not recomputed), as
    //    a further film contact on the piston would hold it, answers as the master's own.
    const FlexibleSurface& first = *sim.contact<SkirtContact>().piston();
    const FlexibleSurface second(first.flexibleBody(), FlexibleSurface::Side::Piston, first.surface(), g);
    EXPECT_EQ(second.flexibleBody().get(), first.flexibleBody().get());
    EXPECT_EQ(second.flexibleBody().get(), sim.pistonBody().get());
    EXPECT_EQ((reducedCompliance(second, g) - reducedCompliance(first, g)).cwiseAbs().maxCoeff(), 0.0);
    std::filesystem::remove_all(dir);
}
