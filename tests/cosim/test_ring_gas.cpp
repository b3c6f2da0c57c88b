// The ring pack's gas (docs/ring-pack.md): the orifice flow against the isentropic nozzle's
// choked formula and its incompressible (Bernoulli) limit, its derivatives against differences; a
// closed volume leaking through a choked gap against the analytic exponential decay, with the
// backward-Euler step's first order; and the gas mass of a two-volume chain over a fired cycle
// (in from the cylinder = blow-by + accumulation).
#include "cosim/ringpack/InterRingGas.hpp"
#include "cosim/ringpack/OrificeFlow.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace flexehd::cosim;

namespace {
const GasProperties kAir{1.4, 287.0};
constexpr double kT = 400.0;  // K
}  // namespace

TEST(OrificeFlow, ChokedAndIncompressibleLimits) {
    const double g = kAir.gamma, cda = 1e-7;
    EXPECT_NEAR(criticalPressureRatio(kAir), 0.528, 5e-4);  // air, the textbook value
    // Choked: ṁ* = C_d A p_u √(γ/(R T)) (2/(γ+1))^{(γ+1)/(2(γ−1))}, for any r below r*.
    const double pu = 10e5, choked = cda * pu * std::sqrt(g / (kAir.gasConstant * kT)) *
                                     std::pow(2.0 / (g + 1.0), (g + 1.0) / (2.0 * (g - 1.0)));
    for (double r : {0.1, 0.3, 0.5})
        EXPECT_NEAR(orificeFlow(kAir, cda, pu, r * pu, kT, kT), choked, 1e-12 * choked);
    // The law is continuous at r* and falls to 0 at r = 1; reversed, it flows the other way.
    const double rs = criticalPressureRatio(kAir);
    EXPECT_NEAR(orificeFlow(kAir, cda, pu, (rs + 1e-9) * pu, kT, kT), choked, 1e-8 * choked);
    EXPECT_DOUBLE_EQ(orificeFlow(kAir, cda, 0.3 * pu, pu, kT, kT), -choked);
    // Small differences: Bernoulli ṁ = C_d A √(2 ρ_u Δp), the leading term of the expansion in
    // ε = Δp/p_u; the next term is O(ε).
    for (double eps : {1e-3, 1e-2}) {
        const double rho = pu / (kAir.gasConstant * kT), bernoulli = cda * std::sqrt(2.0 * rho * eps * pu);
        const double m = orificeFlow(kAir, cda, pu, (1.0 - eps) * pu, kT, kT);
        std::printf("eps %.0e: flow / Bernoulli - 1 = %.3g\n", eps, m / bernoulli - 1.0);
        EXPECT_LT(std::abs(m / bernoulli - 1.0), eps);
    }
}

TEST(OrificeFlow, DerivativesMatchDifferences) {
    const double cda = 2e-7;
    for (const auto& [pa, pb] : std::vector<std::pair<double, double>>{{5e5, 1e5}, {3e5, 2.5e5}, {2e5, 6e5}, {1e5, 1.00001e5}}) {
        double da = 0.0, db = 0.0;
        orificeFlow(kAir, cda, pa, pb, kT, 350.0, &da, &db);
        const double h = 1e-3;  // Pa
        const double fa = (orificeFlow(kAir, cda, pa + h, pb, kT, 350.0) - orificeFlow(kAir, cda, pa - h, pb, kT, 350.0)) / (2 * h);
        const double fb = (orificeFlow(kAir, cda, pa, pb + h, kT, 350.0) - orificeFlow(kAir, cda, pa, pb - h, kT, 350.0)) / (2 * h);
        EXPECT_NEAR(da, fa, 1e-5 * std::abs(fa) + 1e-16);
        EXPECT_NEAR(db, fb, 1e-5 * std::abs(fb) + 1e-16);
    }
}

// A volume V at T leaking through a choked orifice: dp/dt = −p C_d A C* √(γ R T)/V, so
// p = p0 exp(−t/τ) while p_d/p < r*; backward Euler gives p0 (1 + Δt/τ)^−N, first order in Δt.
TEST(InterRingGas, ClosedVolumeLeaksAtTheChokedExponentialRate) {
    const double g = kAir.gamma, V = 1e-6, cda = 1e-7, p0 = 10e5, pd = 1e5;
    const double cstar = std::pow(2.0 / (g + 1.0), (g + 1.0) / (2.0 * (g - 1.0)));
    const double tau = V / (cda * cstar * std::sqrt(g * kAir.gasConstant * kT));
    std::vector<double> err;
    for (int N : {50, 100, 200, 400}) {
        InterRingGas gas(kAir, {V}, {kT}, {0.0, cda}, p0);
        for (int s = 0; s < N; ++s) gas.advance(tau / N, 1e5, pd);
        err.push_back(std::abs(gas.pressures()[0] / (p0 * std::exp(-1.0)) - 1.0));
        std::printf("N %d: p(tau) %.6g Pa (analytic %.6g), error %.3g\n", N, gas.pressures()[0], p0 * std::exp(-1.0),
                    err.back());
    }
    for (std::size_t k = 1; k < err.size(); ++k) EXPECT_NEAR(std::log2(err[k - 1] / err[k]), 1.0, 0.05);
    EXPECT_LT(err.back(), 1.5e-3);  // backward Euler's error ≈ Δt/(2τ) at t = τ: 1.25e-3
}

// Two land volumes between the cylinder and the crankcase over a fired cycle at 1000 rpm (a
// peak of 45 bar at 372°): what enters from the cylinder is the blow-by plus what the volumes
// gain, to the Newton tolerance, step by step and over the cycle.
TEST(InterRingGas, GasMassIsConservedOverAFiredCycle) {
    InterRingGas gas(kAir, {1.2e-6, 0.9e-6}, {450.0, 400.0}, {3e-8, 2.5e-8, 4e-8}, 1e5);
    const double degree = 60.0 / (1000.0 * 360.0), dt = 0.25 * degree;
    const double m0 = gas.mass();
    double in = 0.0, out = 0.0, worst = 0.0, peakLand = 0.0;
    for (int s = 1; s <= 4 * 720; ++s) {
        const double deg = 0.25 * s, pc = 1e5 + 44e5 * std::exp(-std::pow((deg - 372.0) / 30.0, 2));
        const double before = gas.mass();
        gas.advance(dt, pc, 1e5);
        in += gas.flow(0) * dt;
        out += gas.blowBy() * dt;
        worst = std::max(worst, std::abs((gas.mass() - before) - dt * (gas.flow(0) - gas.blowBy())));
        peakLand = std::max(peakLand, gas.pressures()[0]);
    }
    std::printf("in %.4g kg, blow-by %.4g kg, gained %.4g kg, worst step imbalance %.3g kg, land 2 peak %.3g bar\n", in,
                out, gas.mass() - m0, worst, peakLand / 1e5);
    EXPECT_GT(in, 0.0);
    EXPECT_GT(peakLand, 2e5);  // the first land is pressurised by the firing
    EXPECT_LT(std::abs(in - out - (gas.mass() - m0)), 1e-9 * in);
    EXPECT_LT(worst, 1e-10 * in);
    // The blow-by in l/min at normal conditions: air's normal density 1.2922 kg/m³ (DIN 1343).
    EXPECT_NEAR(gas.blowByLitresPerMinute(), gas.blowBy() / 1.2922 * 6e4, 1e-3 * std::abs(gas.blowBy() / 1.2922 * 6e4));
}

// A groove open wide to the cylinder (a lifted top ring's upper flank clearance, 1.09e-5 m²) and
// by a narrow passage to the land below (held at its 6.87 bar), 5 kPa above the cylinder's
// pressure at the step's start (a flexible piston's run on the oil layer at 1000 rpm, 440°):
// across the wide passage the flow's square-root law sends a full Newton step as far past the
// root as it started, and a step that only has to lower the residual a little crawls at 1 % a
// pass. The step converges, to the root of the volume's balance found independently by bisection.
TEST(InterRingGas, AGrooveOpenWideToTheCylinderAtNearlyItsPressureConverges) {
    const double V = 2.2031e-7, T = 450.0, dt = 5.968085e-5, start = 711201.678, pc = 706169.0679,
                 below = 686684.5956, wide = 1.0862e-5, narrow = 3.2e-7;
    std::vector<GasOrifice> o(2);
    o[0].from = GasOrifice::kCylinder, o[0].to = 0, o[0].area = wide;
    o[1].from = 0, o[1].to = GasOrifice::kCrankcase, o[1].area = narrow;
    const GasProperties air{};
    InterRingGas gas(air, {V}, {T}, o, start);
    ASSERT_NO_THROW(gas.advance(dt, pc, below));
    // V/(R T) (p − p_n)/Δt = ṁ_in(p) − ṁ_out(p): decreasing in p.
    auto balance = [&](double p) {
        return orificeFlow(air, wide, pc, p, T, T) - orificeFlow(air, narrow, p, below, T, T) -
               V / (air.gasConstant * T) * (p - start) / dt;
    };
    double lo = below, hi = start;
    for (int it = 0; it < 200; ++it) (balance(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    std::printf("groove at %.6f Pa (bisection %.6f Pa), cylinder %.6f Pa\n", gas.pressures()[0], 0.5 * (lo + hi), pc);
    EXPECT_NEAR(gas.pressures()[0], 0.5 * (lo + hi), 1e-9 * pc);
}

// The gas through a face's open gap (channelFlow): a uniform slit of height h, length b and width
// W, against the momentum balance integrated along it, dp/dx = −12 μ R T ṁ'/(h³ p) (laminar,
// isothermal), from p_a over b by RK4 and the flow ṁ' = ṁ/W found by bisection to land on p_b; its
// derivatives against differences; a wide gap held to its narrowest height's orifice, in series.
TEST(ChannelFlow, ASlitPassesTheIsothermalLaminarFlowOfItsMomentumBalance) {
    const double h = 3e-6, b = 1.2e-3, W = 0.27, pa = 3e5, pb = 1e5, mu = kAir.viscosity, R = kAir.gasConstant;
    const double G = W * h * h * h / b;  // πD/∫dx/h³ for a uniform gap
    auto outlet = [&](double q) {  // p at x = b for a flow q per unit width
        double p = pa;
        const int N = 2000;
        const double dx = b / N;
        auto f = [&](double pp) { return -12.0 * mu * R * kT * q / (h * h * h * pp); };
        for (int k = 0; k < N; ++k) {
            const double k1 = f(p), k2 = f(p + 0.5 * dx * k1), k3 = f(p + 0.5 * dx * k2), k4 = f(p + dx * k3);
            p += dx / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            if (!(p > 0.0)) return -1.0;  // a flow the pressure drop cannot carry over b
        }
        return p;
    };
    double lo = 0.0, hi = 1e-9;
    while (outlet(hi) > pb) hi *= 2.0;
    for (int it = 0; it < 100; ++it) (outlet(0.5 * (lo + hi)) > pb ? lo : hi) = 0.5 * (lo + hi);
    const double reference = W * 0.5 * (lo + hi);
    double da = 0.0, db = 0.0;
    const double m = channelFlow(kAir, G, 0.0, pa, pb, kT, kT, &da, &db);
    std::printf("slit: %.6e kg/s (momentum balance %.6e)\n", m, reference);
    EXPECT_NEAR(m / reference, 1.0, 1e-9);
    EXPECT_NEAR(channelFlow(kAir, G, 0.0, pb, pa, kT, kT), -m, 1e-15);
    const double e = 1.0;
    EXPECT_NEAR(da, (channelFlow(kAir, G, 0.0, pa + e, pb, kT, kT) - channelFlow(kAir, G, 0.0, pa - e, pb, kT, kT)) / (2 * e),
                1e-6 * std::abs(da));
    EXPECT_NEAR(db, (channelFlow(kAir, G, 0.0, pa, pb + e, kT, kT) - channelFlow(kAir, G, 0.0, pa, pb - e, kT, kT)) / (2 * e),
                1e-6 * std::abs(db));
    // The channel in series with its narrowest height's orifice, 1/ṁ = 1/ṁ_channel + 1/ṁ_orifice: a
    // 100 µm gap's laminar flow would be (100/3)³ = 3.7e4 times the 3 µm one's (the momentum
    // balance's above), far beyond the orifice of that height, which then carries it.
    const double wide = 100e-6, area = 0.86 * W * wide, laminar = reference * std::pow(wide / h, 3);
    const double orifice = orificeFlow(kAir, area, pa, pb, kT, kT);
    EXPECT_NEAR(channelFlow(kAir, W * std::pow(wide, 3) / b, area, pa, pb, kT, kT),
                orifice * laminar / (orifice + laminar), 1e-9 * orifice);
    // Smooth where the two are alike (a 20 µm gap) and at equal pressures: slopes as differences.
    for (const double gap : {20e-6, 100e-6})
        for (const double from : {pa, pb + 1e-3}) {
            const double G2 = W * std::pow(gap, 3) / b, A2 = 0.86 * W * gap;
            double sa = 0.0, sb = 0.0;
            channelFlow(kAir, G2, A2, from, pb, kT, kT, &sa, &sb);
            const double d = 1e-4 * (from - pb) + 1e-6;
            auto flow = [&](double x, double y) { return channelFlow(kAir, G2, A2, x, y, kT, kT); };
            EXPECT_NEAR(sa, (flow(from + d, pb) - flow(from - d, pb)) / (2 * d), 1e-5 * std::abs(sa)) << gap << " " << from;
            EXPECT_NEAR(sb, (flow(from, pb + d) - flow(from, pb - d)) / (2 * d), 1e-5 * std::abs(sb)) << gap << " " << from;
        }
    EXPECT_EQ(channelFlow(kAir, 0.0, 0.0, pa, pb, kT, kT), 0.0);
    EXPECT_THROW(channelFlow(kAir, -1.0, 0.0, pa, pb, kT, kT), std::invalid_argument);
}

// A closed volume leaking through a channel alone (InterRingGas with the channel on its orifice):
// V/(R T) dp/dt = −G (p² − p_d²)/(24 μ R T), whose solution is p = p_d coth(a p_d t + arcoth(p0/p_d)),
// a = G/(24 μ V); backward Euler converges to it at first order.
TEST(InterRingGas, AVolumeLeakingThroughAChannelFollowsItsClosedForm) {
    const double V = 1e-7, G = 0.27 * std::pow(4e-6, 3) / 1.2e-3, p0 = 5e5, pd = 1e5;
    const double a = G / (24.0 * kAir.viscosity * V), T = 0.5 / (a * pd);
    const double exact = pd / std::tanh(a * pd * T + std::atanh(pd / p0));
    std::vector<double> err;
    for (int N : {100, 200, 400}) {
        InterRingGas gas(kAir, {V}, {kT}, {0.0, 0.0}, p0);
        gas.setChannel(1, G, 0.0);
        for (int s = 0; s < N; ++s) gas.advance(T / N, 1e5, pd);
        err.push_back(std::abs(gas.pressures()[0] / exact - 1.0));
        std::printf("N %d: p %.6g Pa (closed form %.6g), error %.3g\n", N, gas.pressures()[0], exact, err.back());
    }
    for (std::size_t k = 1; k < err.size(); ++k) EXPECT_NEAR(std::log2(err[k - 1] / err[k]), 1.0, 0.1);
    EXPECT_LT(err.back(), 5e-3);
    InterRingGas gas(kAir, {V}, {kT}, {0.0, 0.0}, p0);
    EXPECT_THROW(gas.setChannel(1, -1.0, 0.0), std::invalid_argument);
}
