// A film contact added to a run brings its own results: the columns it names go to history.csv
// after the master's and its cycle figures to summary.json, with no edit of the master or of a
// writer (docs/results-format.md, "Columns of further contacts"). The contact here is a flooded
// axisymmetric band of constant film thickness h0 around the piston (a ring face worn flat): a
// pure Couette film, whose friction force on the piston is F_z = −η v 2πRL / h0 and whose
// dissipated power is P = η v² 2πRL / h0 for the piston velocity v. v comes from the crank-slider's
// closed form, and the cycle mean of P from a quadrature of it, both written out here.
#include "cosim/contact/FilmContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/results/HistoryWriter.hpp"
#include "cosim/run/CaseRun.hpp"
#include "SmallEngineCase.hpp"
#include "../TestScratch.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

// The band: radius R, axial height L, film h0, viscosity η; rigid bodies only (no modal load).
class BandContact final : public FilmContact {
public:
    BandContact(double radius, double height, double film, double viscosity)
        : area_(2.0 * std::numbers::pi * radius * height), film_(film), viscosity_(viscosity) {}

    ContactState initialState(double linerOffset) const override {
        ContactState s;
        s.linerOffset = linerOffset;
        return s;
    }
    void evaluate(const ContactStep& step, const ContactState&, const ContactState&, const Eigen::Vector2d&,
                  const Eigen::VectorXd&, ContactIterate& it, WorkTally&) override {
        const double v = step.pistonVelocity;  // the liner slides at −v under the piston
        it = ContactIterate{};
        it.loads.shearForce.z() = -viscosity_ * v * area_ / film_;
        it.loads.viscousDissipation = viscosity_ * v * v * area_ / film_;
        it.minGap = film_;
        it.action.fz = it.loads.shearForce.z();  // axisymmetric: no lateral force, no moment (pin on the axis)
    }
    void addModalLoad(const ContactStep&, const ContactIterate&, Eigen::VectorXd&, WorkTally&) const override {}
    double filmChange(const ContactStep&, const Eigen::VectorXd&, WorkTally&) const override { return 0.0; }
    void linearize(const ContactStep&, const ContactState&, const Eigen::Vector2d&, const ContactIterate&,
                   ContactJacobian&, WorkTally&) override {}
    ContactState accepted(const ContactStep& step, const ContactState&, const ContactIterate&) const override {
        return initialState(step.linerOffset);
    }

    std::vector<ContactColumn> columns() const override {
        return {{"band_friction_force_n", {}},
                {"band_friction_power_w", {{"band.friction_power_mean_w", CycleStatistic::Mean},
                                           {"band.friction_power_max_w", CycleStatistic::Maximum}}},
                {"band_film_m", {{"band.film_min_m", CycleStatistic::Minimum}}}};
    }
    void columnValues(const ContactIterate& it, std::vector<double>& values) const override {
        values.push_back(it.loads.shearForce.z());
        values.push_back(it.loads.viscousDissipation);
        values.push_back(it.minGap);
    }

private:
    double area_, film_, viscosity_;
};

constexpr double kBandHeight = 1.5e-3, kBandFilm = 4e-6;

// The piston velocity (m/s, +z towards the head) of the centred crank-slider at crank angle θ
// from TDC: z = r cos θ + √(l² − r² sin² θ), v = dz/dθ ω.
double pistonVelocity(const EngineSpec& e, double deg) {
    const double r = 0.5 * e.stroke, l = e.rodLength, th = deg * std::numbers::pi / 180.0;
    const double omega = e.speedRpm * 2.0 * std::numbers::pi / 60.0;
    const double s = std::sin(th), c = std::cos(th);
    return -r * omega * (s + r * s * c / std::sqrt(l * l - r * r * s * s));
}

std::vector<std::string> splitLine(const std::string& line) {
    std::vector<std::string> f;
    std::stringstream in(line);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    return f;
}

}  // namespace

TEST(ContactColumns, AnAddedContactsColumnsAndFiguresReachHistoryAndSummary) {
    const auto dir = test::scratchDir();
    EngineCase c = test::smallCase();
    ASSERT_EQ(c.engine.pinOffset, 0.0);
    c.output.directory = (dir / "out").string();
    c.output.vtkEveryDeg = 0.0;
    const double radius = 0.5 * c.engine.bore, eta = c.lubricant.viscosity;
    const std::vector<ContactBuilder> band{[&](const EngineCase&, const PistonSimulation&) {
        return std::make_unique<BandContact>(radius, kBandHeight, kBandFilm, eta);
    }};
    runCase(c, {}, band);

    // history.csv: the master's columns as without the band, then the band's.
    std::ifstream in(dir / "out" / "history.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> expected = HistoryWriter::columns(false);
    for (const char* name : {"band_friction_force_n", "band_friction_power_w", "band_film_m"}) expected.push_back(name);
    ASSERT_EQ(splitLine(line), expected);
    const std::size_t crank = 1, force = expected.size() - 3, power = force + 1, film = force + 2;
    const double area = 2.0 * std::numbers::pi * radius * kBandHeight;
    int rows = 0;
    double firstDeg = 0.0, worst = 0.0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> f = splitLine(line);
        ASSERT_EQ(f.size(), expected.size());
        const double deg = std::stod(f[crank]), v = pistonVelocity(c.engine, deg);
        if (rows++ == 0) firstDeg = deg;
        const double scale = eta * area / kBandFilm;  // N per m/s
        const double vmax = 0.5 * c.engine.stroke * c.engine.speedRpm * 2.0 * std::numbers::pi / 60.0 * 1.1;
        worst = std::max(worst, std::abs(std::stod(f[force]) + scale * v) / (scale * vmax));
        worst = std::max(worst, std::abs(std::stod(f[power]) - scale * v * v) / (scale * vmax * vmax));
        EXPECT_EQ(std::stod(f[film]), kBandFilm);
    }
    EXPECT_GT(rows, 700);
    EXPECT_LT(worst, 1e-8);  // the 9 printed digits

    // summary.json: the band's figures of the cycle against the closed form's quadrature over the
    // records' span (Simpson, 20000 intervals) and its exact extremes.
    std::ifstream s(dir / "out" / "summary.json");
    const nlohmann::json d = nlohmann::json::parse(s);
    const int n = 20000;
    double integral = 0.0, largest = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double deg = firstDeg + (720.0 - firstDeg) * k / n, v = pistonVelocity(c.engine, deg);
        const double p = eta * area / kBandFilm * v * v;
        integral += (k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0) * p;
        largest = std::max(largest, p);
    }
    const double mean = integral / (3.0 * n);
    EXPECT_NEAR(d.at("band").at("friction_power_mean_w").get<double>(), mean, 1e-4 * mean);
    EXPECT_NEAR(d.at("band").at("friction_power_max_w").get<double>(), largest, 1e-3 * largest);
    EXPECT_EQ(d.at("band").at("film_min_m").get<double>(), kBandFilm);
    // The skirt's own figures are still there.
    EXPECT_TRUE(d.contains("friction_power_mean_w"));
    EXPECT_TRUE(d.contains("min_film_m"));
}

TEST(ContactColumns, HistoryWriterRefusesBadContactColumnsAndValues) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "history.csv").string();
    EXPECT_NE(test::errorOf([&] { HistoryWriter(path, false, {"a b"}); }).find("'a b'"), std::string::npos);
    EXPECT_NE(test::errorOf([&] { HistoryWriter(path, false, {""}); }).find("no comma or space"), std::string::npos);
    EXPECT_NE(test::errorOf([&] { HistoryWriter(path, false, {"lateral_m"}); }).find("twice"), std::string::npos);
    EXPECT_NE(test::errorOf([&] { HistoryWriter(path, false, {"x_m", "x_m"}); }).find("twice"), std::string::npos);

    HistoryWriter w(path, false, {"band_film_m"});
    StepRecord r;
    r.crankDeg = 12.5;
    r.contactValues = {std::numeric_limits<double>::quiet_NaN()};
    EXPECT_NE(test::errorOf([&] { w.append(r); }).find("column 'band_film_m' is nan at crank angle 12.5"),
              std::string::npos);
    r.contactValues = {};
    EXPECT_NE(test::errorOf([&] { w.append(r); }).find("0 contact values for 1 contact columns"), std::string::npos);
    r.contactValues = {3e-6};
    w.append(r);
    // The file holds the header and the one good row; reading it back ignores the extra column.
    const std::vector<StepRecord> back = HistoryWriter::read(path);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].crankDeg, 12.5);
}
