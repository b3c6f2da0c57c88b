// The partitioned film–structure coupling of PistonSimulation (film solve, then the quasi-static
// modal response, accelerated by IQN-ILS) converges to the same state as a monolithic solve of
// the same equations (docs/coupling.md §2).
//
// At written crank angles of an EHD run the test takes the piston's rigid motion (e, β, ė, β̇)
// from the run and solves, from scratch and as one system, for the film pressure p and the
// piston's modal coordinates q:
//     min(p_k − p_cav, (A(h) p − b(h))_k / A_kk) = 0     on film nodes (Reynolds cavitation LCP)
//     (A(h) p − b(h))_k = 0                             on prescribed nodes (identity rows)
//     q − G p = 0                                       (quasi-static response, G = C Φᵀ A_map)
//     h = h_rigid(e, β) + Δh(q)
// by damped semismooth Newton (primal–dual active set) with the exact derivative in p and finite
// differences in q, on a dense LU. This uses neither the multigrid solver nor the coupling
// accelerator; only the discretisation (ReynoldsSystem) and the body (FlexibleSurface) are shared.
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <filesystem>
#include <numbers>

using namespace flexehd::cosim;
namespace lube = flexehd::lube;
namespace fs = std::filesystem;

namespace {

// The small flexible-piston engine (SmallEngineCase.hpp) with a tight coupling tolerance.
EngineCase tightlyCoupledCase(const std::string& pistonFile) {
    EngineCase c = flexehd::test::smallFlexibleCase(pistonFile);
    c.time.maxCycles = 1;
    c.output.vtkEveryDeg = 15.0;
    // A tight coupling tolerance, so that the comparison below is sharp.
    c.coupling.tolerance = 1e-6;
    c.coupling.maxIterations = 60;
    // The monolithic reference below has the rigid film thickness's rate in the squeeze term.
    c.coupling.elasticSqueeze = false;
    return c;
}

struct Monolithic {
    Eigen::VectorXd p, q;
    int iterations = 0;
    double residual = 0.0;
    // How far the partitioned iteration may stop from this solution. It stops at modal
    // coordinates y with max|Ψ r| ≤ tol·c on the film, r = H(y) − y; linearised,
    // y − q = −S⁻¹ r with S = I − ∂H/∂q = I + G J_pp⁻¹ J_pq (the Schur complement of the
    // Jacobian), and p(y) − p = −J_pp⁻¹ J_pq (y − q). With r = Ψ⁺ Ψ r (Ψ of full column rank):
    //   max|Ψ (y − q)| ≤ κ_h tol·c,  κ_h = ‖Ψ S⁻¹ Ψ⁺‖_∞;   max|p(y) − p| ≤ κ_p tol·c,
    //   κ_p = ‖J_pp⁻¹ J_pq S⁻¹ Ψ⁺‖_∞.
    double kappaH = 0.0, kappaP = 0.0;

    void sensitivity(const Eigen::MatrixXd& J, const Eigen::MatrixXd& Psi, const lube::FilmGrid& g) {
        const int n = g.size(), m = int(Psi.cols());
        std::vector<int> rows;
        for (int k = 0; k < n; ++k)
            if (g.kind(k) != lube::NodeKind::Void) rows.push_back(k);
        Eigen::MatrixXd PsiF(rows.size(), m);
        for (std::size_t i = 0; i < rows.size(); ++i) PsiF.row(i) = Psi.row(rows[i]);
        const Eigen::MatrixXd dpdq = -J.topLeftCorner(n, n).partialPivLu().solve(J.topRightCorner(n, m));
        const Eigen::MatrixXd S = Eigen::MatrixXd::Identity(m, m) + J.bottomLeftCorner(m, n) * dpdq;
        const Eigen::MatrixXd SinvPinv = S.partialPivLu().solve(PsiF.completeOrthogonalDecomposition().pseudoInverse());
        kappaH = (PsiF * SinvPinv).cwiseAbs().rowwise().sum().maxCoeff();
        kappaP = (dpdq * SinvPinv).cwiseAbs().rowwise().sum().maxCoeff();
    }
};

// Semismooth Newton on (p, q) for the rigid motion of one step; see the file comment.
// Starts from q0 (must leave a positive film); returns iterations = 0 if it does not.
Monolithic solveMonolithic(const PistonSimulation& sim, const EngineCase& c, double lateral, double tilt,
                           double lateralVelocity, double tiltRate, double slidingVelocity, const Eigen::VectorXd& q0) {
    const SkirtFilm& film = sim.contact<SkirtContact>().film();
    const lube::FilmGrid& g = film.grid();
    const FlexibleSurface& body = *sim.contact<SkirtContact>().piston();
    const int n = g.size(), m = body.modes();
    Eigen::VectorXd hRigid;
    film.rigidThickness(lateral, tilt, hRigid);
    lube::FilmState fs;
    fs.outer.axial = -slidingVelocity;
    // ∂h/∂t of the rigid film thickness (the coupling leaves the elastic rate out, docs/coupling.md §3).
    fs.dhdt = -(lateralVelocity * Eigen::VectorXd::Ones(n) + tiltRate * film.nodeZ()).cwiseProduct(film.nodeCos());
    for (int k = 0; k < n; ++k)
        if (g.kind(k) == lube::NodeKind::Void) fs.dhdt[k] = 0.0;
    const double rho = c.lubricant.density, eta = c.lubricant.viscosity, pcav = c.lubricant.cavitationPressure;

    // G: the quasi-static response is linear in p; its columns are the responses to unit pressures.
    Eigen::MatrixXd G(m, n);
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), col;
    for (int k = 0; k < n; ++k) {
        unit[k] = 1.0;
        body.respond(unit, 0.0, col);
        G.col(k) = col;
        unit[k] = 0.0;
    }
    // Ψ: the film-thickness change per modal coordinate (filmChange is linear in q).
    Eigen::MatrixXd Psi(n, m);
    for (int j = 0; j < m; ++j) {
        Eigen::VectorXd e = Eigen::VectorXd::Zero(m);
        e[j] = 1.0;
        body.filmChange(e, 0.0, col);
        Psi.col(j) = col;
    }
    auto thickness = [&](const Eigen::VectorXd& q) {
        Eigen::VectorXd dh;
        body.filmChange(q, 0.0, dh);
        return Eigen::VectorXd(hRigid + dh);
    };
    // w(p, q) = A(h(q)) p − b(h(q)) and the diagonal of A.
    auto flux = [&](const Eigen::VectorXd& p, const Eigen::VectorXd& q, Eigen::VectorXd* diag, lube::SparseMatrix* A) {
        fs.h = thickness(q);
        lube::ReynoldsSystem sys(g, fs, rho, eta);
        if (diag) *diag = sys.diagonal();
        if (A) *A = sys.matrix();
        return Eigen::VectorXd(sys.matrix() * p - sys.rhs());
    };

    Monolithic r;
    r.q = q0;
    {
        fs.h = thickness(q0);
        for (int k = 0; k < n; ++k)
            if (g.kind(k) != lube::NodeKind::Void && !(fs.h[k] > 0.0)) return r;
        lube::ReynoldsSystem sys(g, fs, rho, eta);
        r.p = sys.initialGuess(pcav);
    }
    Eigen::VectorXd d;
    lube::SparseMatrix A;
    for (r.iterations = 1; r.iterations <= 60; ++r.iterations) {
        const Eigen::VectorXd w = flux(r.p, r.q, &d, &A);
        // Active set: film nodes where the bound is the smaller branch of the min-function.
        std::vector<char> bound(n, 0);
        Eigen::VectorXd F(n + m);
        double pScale = 1.0;
        for (int k = 0; k < n; ++k) pScale = std::max(pScale, std::abs(r.p[k]));
        double resP = 0.0;
        for (int k = 0; k < n; ++k) {
            if (g.kind(k) == lube::NodeKind::Film && r.p[k] - pcav <= w[k] / d[k]) {
                bound[k] = 1;
                F[k] = r.p[k] - pcav;
            } else {
                F[k] = w[k] / d[k];
            }
            resP = std::max(resP, std::abs(F[k]));
        }
        F.tail(m) = r.q - G * r.p;
        Eigen::VectorXd dhq;
        body.filmChange(F.tail(m), 0.0, dhq);
        r.residual = resP / pScale + dhq.cwiseAbs().maxCoeff() / c.piston.clearance;

        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + m, n + m);
        const Eigen::MatrixXd Ad(A);
        for (int k = 0; k < n; ++k) {
            if (bound[k]) J(k, k) = 1.0;
            else J.row(k).head(n) = Ad.row(k) / d[k];
        }
        for (int j = 0; j < m; ++j) {
            // Finite difference in q_j, with the active set and the scaling held.
            Eigen::VectorXd qj = r.q;
            const double dq = 1e-7 * std::max(1.0, std::abs(r.q[j]));
            qj[j] += dq;
            const Eigen::VectorXd wj = flux(r.p, qj, nullptr, nullptr);
            for (int k = 0; k < n; ++k)
                if (!bound[k]) J(k, n + j) = (wj[k] - w[k]) / d[k] / dq;
        }
        J.bottomLeftCorner(m, n) = -G;
        J.bottomRightCorner(m, m).setIdentity();
        if (r.residual < 1e-11) {
            r.sensitivity(J, Psi, g);
            break;
        }
        const Eigen::VectorXd step = J.partialPivLu().solve(-F);
        // Damped: halve the step until the film thickness stays positive on the film.
        double t = 1.0;
        for (;; t *= 0.5) {
            const Eigen::VectorXd h = thickness(r.q + t * step.tail(m));
            bool positive = true;
            for (int k = 0; k < n; ++k) positive = positive && (g.kind(k) == lube::NodeKind::Void || h[k] > 0.0);
            if (positive || t < 1e-6) break;
        }
        r.p += t * step.head(n);
        r.q += t * step.tail(m);
    }
    return r;
}

}  // namespace

TEST(CouplingMonolithic, PartitionedIterationMatchesTheMonolithicSolve) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_mono_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = flexehd::test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;

    const EngineCase c = tightlyCoupledCase(file);
    PistonSimulation sim(c);
    std::vector<StepRecord> steps;
    std::vector<Snapshot> snaps;
    SimulationCallbacks cb;
    cb.onStep = [&](const StepRecord& r) { steps.push_back(r); };
    cb.onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); };
    sim.run(cb, 420.0);  // through the firing slap
    ASSERT_GE(snaps.size(), 4u);
    const FlexibleSurface& piston = *sim.contact<SkirtContact>().piston();
    const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();

    int compared = 0, skipped = 0;
    double peak = 0.0;
    Eigen::VectorXd previous;
    for (const Snapshot& s : snaps) {
        if (s.contactPressure.cwiseAbs().maxCoeff() > 0.0) continue;  // asperity contact: not in the check
        const StepRecord* r = nullptr;
        for (const auto& st : steps)
            if (std::abs(st.crankDeg - s.crankDeg) < 1e-9) r = &st;
        ASSERT_NE(r, nullptr) << "no step record at " << s.crankDeg << "°";
        const double v = sim.kinematics().at(s.crankDeg).velocity;  // the run starts at 0°
        // Start from the undeformed skirt, or where the rigid film alone is closed (the skirt's
        // elastic give opens it) by continuation from the previous angle's monolithic solution.
        Monolithic mono = solveMonolithic(sim, c, s.lateral, s.tilt, r->lateralVelocity, r->tiltRate, v,
                                          Eigen::VectorXd::Zero(piston.modes()));
        if (mono.iterations == 0 && previous.size() > 0)
            mono = solveMonolithic(sim, c, s.lateral, s.tilt, r->lateralVelocity, r->tiltRate, v, previous);
        if (mono.iterations == 0) {
            std::printf("%6.1f°: no start with a positive film, skipped\n", s.crankDeg);
            ++skipped;
            continue;
        }
        previous = mono.q;
        ASSERT_LT(mono.residual, 1e-11) << "monolithic Newton did not converge at " << s.crankDeg << "°";

        // Distance of the partitioned result from the monolithic one, on the film (non-Void)
        // nodes where the coupling criterion is taken, against the bound of its stopping
        // criterion (Monolithic::kappaH/kappaP; 1.5 for the linearisation, and 1e-6 p_max for
        // the film solver's own tolerance, relative residual 1e-8).
        Eigen::VectorXd dh, elastic;
        piston.filmChange(s.pistonModal - mono.q, 0.0, dh);
        piston.filmChange(mono.q, 0.0, elastic);
        double dhMax = 0.0, dp = 0.0;
        for (int k = 0; k < g.size(); ++k) {
            if (g.kind(k) == lube::NodeKind::Void) continue;
            dhMax = std::max(dhMax, std::abs(dh[k]));
            dp = std::max(dp, std::abs(s.pressure[k] - mono.p[k]));
        }
        const double pmax = mono.p.cwiseAbs().maxCoeff();
        const double tolH = c.coupling.tolerance * c.piston.clearance;
        std::printf("%6.1f°: p_max %.3g Pa, elastic Δh max %.3g m, |Δh| %.2g m (bound %.2g), |Δp| %.2g Pa "
                    "(bound %.2g), Newton %d\n", s.crankDeg, pmax, elastic.cwiseAbs().maxCoeff(), dhMax,
                    1.5 * mono.kappaH * tolH, dp, 1.5 * mono.kappaP * tolH + 1e-6 * pmax, mono.iterations);
        EXPECT_LT(dhMax, 1.5 * mono.kappaH * tolH) << s.crankDeg;
        EXPECT_LT(dp, 1.5 * mono.kappaP * tolH + 1e-6 * pmax) << s.crankDeg;
        peak = std::max(peak, elastic.cwiseAbs().maxCoeff());
        ++compared;
    }
    EXPECT_GE(compared, 20);
    EXPECT_LE(skipped, 2);
    // The check is not vacuous: the skirt deforms by a visible fraction of the clearance.
    EXPECT_GT(peak, 0.01 * c.piston.clearance);
    fs::remove_all(dir);
}
