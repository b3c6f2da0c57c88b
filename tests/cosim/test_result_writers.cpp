// Result writers of a run: history.csv (HistoryWriter), the VTK series (FieldSeriesWriter) and the
// mode shapes (ModeShapeExport).
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "cosim/results/FieldSeriesWriter.hpp"
#include "cosim/results/HistoryWriter.hpp"
#include "cosim/results/ModeShapeExport.hpp"
#include "tests/fem/TestData.hpp"
#include "TestFiles.hpp"
#include "VtkReadBack.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using test::PvdEntry;
using test::readPvd;
using test::readVts;
using test::readVtu;

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

// A record whose values exercise the printed precision: long mantissas, tiny and huge
// magnitudes, negative values and a negative zero.
StepRecord sampleRecord(int k) {
    StepRecord r;
    r.cycle = 1 + k / 3;
    r.crankDeg = 0.1 * k + 1.0 / 3.0;
    r.time = 1.23456789012345e-3 * (k + 1);
    r.lateral = -2.718281828459045e-5 * (k + 1);
    r.tilt = 3.141592653589793e-4 / (k + 1);
    r.lateralVelocity = (k % 2 ? -1.0 : 1.0) * 1.0e-300;
    r.tiltRate = -0.0;
    r.sideForce = 12345.678901234 * (k - 1);
    r.filmForce = -9876.54321098765;
    r.filmMoment = 1.0 / 7.0;
    r.contactForce = 0.0;
    r.frictionForce = -42.000000001;
    r.linerHydrodynamicFriction = 41.5;
    r.linerBoundaryFriction = -1.0 / 3.0;
    r.dissipatedPower = 1.0e6 / 3.0;
    r.boundaryFrictionPower = 2.0 / 3.0;
    r.cylinderPressure = 4.5e6 + k;
    r.minFilm = 1.234567890123e-6;
    r.maxPressure = 7.77777777777e7;
    r.couplingIterations = 3 + k;
    r.stepDeg = 0.0625;
    return r;
}

// What the file holds for v: v rounded to the printed 9 significant digits.
double printed(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return std::strtod(buf, nullptr);
}

void expectPrintedEqual(const StepRecord& written, const StepRecord& read) {
    EXPECT_EQ(read.cycle, written.cycle);
    EXPECT_EQ(read.couplingIterations, written.couplingIterations);
    const double StepRecord::*reals[] = {&StepRecord::crankDeg,        &StepRecord::time,
                                         &StepRecord::lateral,         &StepRecord::tilt,
                                         &StepRecord::lateralVelocity, &StepRecord::tiltRate,
                                         &StepRecord::sideForce,       &StepRecord::filmForce,
                                         &StepRecord::filmMoment,      &StepRecord::contactForce,
                                         &StepRecord::frictionForce,   &StepRecord::dissipatedPower,
                                         &StepRecord::linerHydrodynamicFriction, &StepRecord::linerBoundaryFriction,
                                         &StepRecord::boundaryFrictionPower, &StepRecord::cylinderPressure,
                                         &StepRecord::minFilm,         &StepRecord::maxPressure,
                                         &StepRecord::stepDeg};
    for (auto m : reals) EXPECT_EQ(read.*m, printed(written.*m));  // exact, not approximate
}

// The header is the first line (numpy.genfromtxt(names=True) takes its names from there and
// skips the '#' lines after it), then the comment lines.
TEST(HistoryWriter, HeaderWithUnitsIsTheFirstLineThenComments) {
    const auto path = test::scratchDir() / "history.csv";
    { HistoryWriter w(path.string()); }
    const auto l = lines(path);
    ASSERT_GE(l.size(), 3u);
    const std::size_t k = 0;
    std::size_t comments = 0;
    while (comments + 1 < l.size() && l[comments + 1].rfind('#', 0) == 0) ++comments;
    EXPECT_GE(comments, 2u) << "expected a few '#' comment lines";
    ASSERT_EQ(comments + 1, l.size());
    EXPECT_THAT(l[k], AllOf(HasSubstr("crank_deg,time_s,lateral_m,tilt_rad,"), HasSubstr("side_force_n"),
                            HasSubstr("dissipated_power_w"), HasSubstr("min_film_m"), HasSubstr("max_pressure_pa"),
                            HasSubstr("coupling_iterations")));
    std::string joined;
    for (const auto& c : HistoryWriter::columns()) joined += (joined.empty() ? "" : ",") + c;
    EXPECT_EQ(l[k], joined);
    EXPECT_TRUE(HistoryWriter::read(path.string()).empty());
}

TEST(HistoryWriter, RoundTripIsExactToThePrintedPrecision) {
    const auto path = test::scratchDir() / "history.csv";
    std::vector<StepRecord> written;
    {
        HistoryWriter w(path.string());
        for (int k = 0; k < 7; ++k) {
            written.push_back(sampleRecord(k));
            w.append(written.back());
            // Flushed line by line: complete while the writer is still open.
            EXPECT_EQ(HistoryWriter::read(path.string()).size(), std::size_t(k + 1));
        }
    }
    bool partial = true;
    const auto read = HistoryWriter::read(path.string(), &partial);
    EXPECT_FALSE(partial);
    ASSERT_EQ(read.size(), written.size());
    for (std::size_t k = 0; k < read.size(); ++k) expectPrintedEqual(written[k], read[k]);
    EXPECT_TRUE(std::signbit(read[0].tiltRate));  // -0 stays -0
    EXPECT_THAT(slurp(path), ::testing::Not(HasSubstr("nan")));
}

TEST(HistoryWriter, TruncatesAnExistingFile) {
    const auto path = test::scratchDir() / "history.csv";
    {
        HistoryWriter w(path.string());
        w.append(sampleRecord(0));
        w.append(sampleRecord(1));
    }
    { HistoryWriter w(path.string()); }
    EXPECT_TRUE(HistoryWriter::read(path.string()).empty());
}

TEST(HistoryWriter, NonFiniteValueIsRefusedNamingColumnAndCrankAngle) {
    const auto path = test::scratchDir() / "history.csv";
    HistoryWriter w(path.string());
    w.append(sampleRecord(0));
    const auto before = slurp(path);
    StepRecord bad = sampleRecord(1);
    bad.crankDeg = 361.25;
    bad.tilt = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { w.append(bad); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("'tilt_rad'"), HasSubstr("361.25"))));
    bad.tilt = 0.0;
    bad.dissipatedPower = -std::numeric_limits<double>::infinity();
    EXPECT_THAT([&] { w.append(bad); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("'dissipated_power_w'"), HasSubstr("361.25"))));
    EXPECT_EQ(slurp(path), before) << "a refused record must leave no partial line";
    w.append(sampleRecord(2));  // the writer stays usable
    EXPECT_EQ(HistoryWriter::read(path.string()).size(), 2u);
}

// A row that does not fit (here the file-size limit, RLIMIT_FSIZE, in place of a full disk: the
// write stops part-way through the row) is cut back: the file ends with the row before, the
// error names the file and the reason in words, and nothing of the failed row is written later.
TEST(HistoryWriter, ARowThatCannotBeWrittenIsCutBackAndTheReasonNamed) {
    const auto path = test::scratchDir() / "history.csv";
    HistoryWriter w(path.string());
    for (int k = 0; k < 3; ++k) w.append(sampleRecord(k));
    const std::string before = slurp(path);
    rlimit old{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldSignal = std::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead
    rlimit small = old;
    small.rlim_cur = before.size() + 40;  // room for 40 bytes of the next row only
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string message;
    try {
        w.append(sampleRecord(3));
    } catch (const std::runtime_error& e) {
        message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldSignal);
    EXPECT_THAT(message, AllOf(HasSubstr("history.csv"), HasSubstr("EFBIG"), HasSubstr("keeps what was written before")));
    EXPECT_EQ(slurp(path), before) << "the failed row must not stay in part";
    w.append(sampleRecord(4));  // room again: the next row follows the last whole one
    const auto read = HistoryWriter::read(path.string());
    ASSERT_EQ(read.size(), 4u);
    expectPrintedEqual(sampleRecord(4), read[3]);
}

// A run killed while writing a line leaves it without its newline: read() returns the complete
// lines before it and reports the partial one.
TEST(HistoryWriter, PartialLastLineOfAKilledRunIsDropped) {
    const auto path = test::scratchDir() / "history.csv";
    {
        HistoryWriter w(path.string());
        for (int k = 0; k < 3; ++k) w.append(sampleRecord(k));
    }
    const std::string complete = slurp(path);
    const std::string fourth = [&] {
        const auto p2 = path.parent_path() / "one.csv";
        HistoryWriter w(p2.string());
        w.append(sampleRecord(3));
        const auto l = lines(p2);
        return l.back();
    }();
    // Cut the fourth line anywhere, even inside its last number.
    for (std::size_t cut : {std::size_t(1), fourth.size() / 2, fourth.size() - 1, fourth.size()}) {
        std::ofstream(path, std::ios::trunc) << complete << fourth.substr(0, cut);
        bool partial = false;
        const auto read = HistoryWriter::read(path.string(), &partial);
        EXPECT_TRUE(partial) << "cut at " << cut;
        ASSERT_EQ(read.size(), 3u) << "cut at " << cut;
        expectPrintedEqual(sampleRecord(2), read[2]);
    }
    // With its newline the fourth line counts.
    std::ofstream(path, std::ios::trunc) << complete << fourth << '\n';
    bool partial = true;
    EXPECT_EQ(HistoryWriter::read(path.string(), &partial).size(), 4u);
    EXPECT_FALSE(partial);
}

TEST(HistoryWriter, ReadGivesClearErrors) {
    const auto dir = test::scratchDir();
    EXPECT_THAT([&] { HistoryWriter::read((dir / "missing.csv").string()); },
                ThrowsMessage<std::runtime_error>(HasSubstr("missing.csv")));

    std::ofstream(dir / "empty.csv").flush();
    EXPECT_THAT([&] { HistoryWriter::read((dir / "empty.csv").string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("empty.csv"), HasSubstr("no header"))));

    std::ofstream(dir / "other.csv") << "# something else\ncrank_deg,time_s\n0,0\n";
    EXPECT_THAT([&] { HistoryWriter::read((dir / "other.csv").string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("other.csv"), HasSubstr("'cycle'"))));

    const auto good = dir / "history.csv";
    {
        HistoryWriter w(good.string());
        w.append(sampleRecord(0));
    }
    const auto l = lines(good);
    const std::string badLine = "line " + std::to_string(l.size() + 1);  // the appended row
    std::string row = l.back();
    const auto bad = dir / "bad.csv";
    // A non-number in the lateral_m column (the 4th).
    std::string corrupt = row;
    std::size_t pos = 0;
    for (int c = 0; c < 3; ++c) pos = corrupt.find(',', pos) + 1;
    corrupt.replace(pos, corrupt.find(',', pos) - pos, "abc");
    std::ofstream(bad) << slurp(good) << corrupt << '\n';
    EXPECT_THAT([&] { HistoryWriter::read(bad.string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr(badLine),
                                                        HasSubstr("'lateral_m'"), HasSubstr("'abc'"))));
    // A missing value.
    std::ofstream(bad, std::ios::trunc) << slurp(good) << row.substr(0, row.rfind(',')) << '\n';
    EXPECT_THAT([&] { HistoryWriter::read(bad.string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr(badLine),
                                                        HasSubstr("values"))));
    // NaN typed in by hand.
    corrupt = row;
    corrupt.replace(pos, corrupt.find(',', pos) - pos, "nan");
    std::ofstream(bad, std::ios::trunc) << slurp(good) << corrupt << '\n';
    EXPECT_THAT([&] { HistoryWriter::read(bad.string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("'lateral_m'"), HasSubstr("finite"))));
    // A fractional iteration count.
    corrupt = row.substr(0, row.rfind(','));
    corrupt = corrupt.substr(0, corrupt.rfind(',')) + ",2.5," + row.substr(row.rfind(',') + 1);
    std::ofstream(bad, std::ios::trunc) << slurp(good) << corrupt << '\n';
    EXPECT_THAT([&] { HistoryWriter::read(bad.string()); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("'coupling_iterations'"), HasSubstr("integer"))));
}

// ---------------------------------------------------------------------------------------------
// FieldSeriesWriter

struct FilmFixture {
    lube::FilmGrid grid;
    FilmField film;
    explicit FilmFixture(lube::FilmGrid g) : grid(std::move(g)) {
        film.grid = &grid;
        film.origin = Eigen::Vector3d(1.0e-5, -2.0e-6, -0.05);
        const Eigen::Index n = grid.size();
        film.pressure = Eigen::VectorXd::LinSpaced(n, 1.0e5, 3.0e7);
        film.filmThickness = Eigen::VectorXd::LinSpaced(n, 2.0e-6, 60.0e-6);
        film.contactPressure = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0e6);
        film.shearStress = Eigen::VectorXd::LinSpaced(n, -1.0e4, 1.0e4);
        film.cavitation = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
    }
};

const std::vector<double> kAxial{0.0, 0.004, 0.010, 0.018, 0.030};  // non-uniform

SnapshotTime at(double time) { return {time, std::fmod(time, 720.0), std::isfinite(time) ? 1 + int(time / 720.0) : 1}; }

// Checks point (i, jj) of the .vts against film node (i, jj mod nθ).
void expectFilmNode(vtkStructuredGrid* vts, const FilmFixture& f, int i, int jj) {
    const lube::FilmGrid& g = f.grid;
    int dims[3];
    vts->GetDimensions(dims);
    const vtkIdType id = vtkIdType(i) * dims[0] + jj;
    const int j = jj % g.nTheta();
    const int k = g.index(i, j);
    double x[3];
    vts->GetPoint(id, x);
    const double R = g.radius();
    EXPECT_NEAR(x[0], f.film.origin.x() + R * std::cos(g.theta(j)), 1e-15) << "i " << i << " jj " << jj;
    EXPECT_NEAR(x[1], f.film.origin.y() + R * std::sin(g.theta(j)), 1e-15) << "i " << i << " jj " << jj;
    EXPECT_DOUBLE_EQ(x[2], f.film.origin.z() + g.z(i)) << "i " << i << " jj " << jj;
    auto* pd = vts->GetPointData();
    const std::pair<const char*, const Eigen::VectorXd*> fields[] = {
        {"pressure_pa", &f.film.pressure},
        {"film_thickness_m", &f.film.filmThickness},
        {"contact_pressure_pa", &f.film.contactPressure},
        {"shear_stress_pa", &f.film.shearStress},
        {"cavitation_fraction", &f.film.cavitation}};
    for (const auto& [name, values] : fields) {
        vtkDataArray* a = pd->GetArray(name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_EQ(a->GetTuple1(id), (*values)(k)) << name << " at i " << i << " jj " << jj;  // float64: exact
    }
    ASSERT_NE(pd->GetArray("node_kind"), nullptr);
    EXPECT_EQ(pd->GetArray("node_kind")->GetTuple1(id), double(static_cast<int>(g.kind(k))));
}

TEST(FieldSeriesWriter, PeriodicFilmIsClosedAtTheSeam) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 12, 0.1));
    f.grid.voidNode(f.grid.index(2, 3));
    FieldSeriesWriter w(dir.string());
    w.write(at(360.0), f.film, nullptr, nullptr);

    const auto vts = readVts(dir / "vtk" / "film_000000.vts");
    int dims[3];
    vts->GetDimensions(dims);
    EXPECT_EQ(dims[0], 13);  // nθ + 1: the seam column
    EXPECT_EQ(dims[1], 5);
    EXPECT_EQ(dims[2], 1);
    EXPECT_EQ(vts->GetNumberOfPoints(), 13 * 5);
    EXPECT_EQ(vts->GetNumberOfCells(), 12 * 4);
    for (int i : {0, 2, 4})
        for (int jj : {0, 1, 3, 7, 11, 12}) expectFilmNode(vts, f, i, jj);
    // The seam column coincides with the first one.
    for (int i = 0; i < 5; ++i) {
        double a[3], b[3];
        vts->GetPoint(vtkIdType(i) * 13, a);
        vts->GetPoint(vtkIdType(i) * 13 + 12, b);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]);
    }
    EXPECT_EQ(vts->GetPointData()->GetArray("node_kind")->GetTuple1(2 * 13 + 3), 2.0);  // Void
    EXPECT_EQ(vts->GetPointData()->GetArray("node_kind")->GetTuple1(0), 1.0);           // Fixed edge
    EXPECT_EQ(vts->GetPointData()->GetArray("node_kind")->GetTuple1(13 + 5), 0.0);      // Film
    ASSERT_NE(vts->GetFieldData()->GetArray("TimeValue"), nullptr);
    EXPECT_EQ(vts->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 360.0);
    ASSERT_NE(vts->GetFieldData()->GetArray("crank_deg"), nullptr);
    EXPECT_EQ(vts->GetFieldData()->GetArray("crank_deg")->GetTuple1(0), 360.0);
    ASSERT_NE(vts->GetFieldData()->GetArray("cycle"), nullptr);
    EXPECT_EQ(vts->GetFieldData()->GetArray("cycle")->GetTuple1(0), 1.0);
}

TEST(FieldSeriesWriter, OpenArcHasNoSeamAndOptionalFieldsMayBeLeftOut) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::arc(0.043, kAxial, -0.8, 0.8, 9));
    FieldSeriesWriter w(dir.string());
    w.write(at(0.5), f.film, nullptr, nullptr);
    auto vts = readVts(dir / "vtk" / "film_000000.vts");
    int dims[3];
    vts->GetDimensions(dims);
    EXPECT_EQ(dims[0], 9);
    EXPECT_EQ(dims[1], 5);
    EXPECT_EQ(vts->GetNumberOfPoints(), 45);
    for (int i : {0, 3, 4})
        for (int jj : {0, 4, 8}) expectFilmNode(vts, f, i, jj);

    f.film.contactPressure.resize(0);
    f.film.shearStress.resize(0);
    f.film.cavitation.resize(0);
    w.write(at(1.0), f.film, nullptr, nullptr);
    vts = readVts(dir / "vtk" / "film_000001.vts");
    EXPECT_NE(vts->GetPointData()->GetArray("pressure_pa"), nullptr);
    EXPECT_NE(vts->GetPointData()->GetArray("film_thickness_m"), nullptr);
    EXPECT_EQ(vts->GetPointData()->GetArray("contact_pressure_pa"), nullptr);
    EXPECT_EQ(vts->GetPointData()->GetArray("cavitation_fraction"), nullptr);
}

fem::Mesh oneTet() {
    fem::Mesh m;
    m.nodes.resize(3, 4);
    m.nodes << 0.0, 0.01, 0.0, 0.0,  //
        0.0, 0.0, 0.01, 0.0,         //
        0.0, 0.0, 0.0, 0.01;
    m.nodeTags = {11, 12, 13, 14};
    m.volume.type = fem::ElementType::Tet4;
    m.volume.nodes.resize(4, 1);
    m.volume.nodes << 0, 1, 2, 3;
    m.volume.tags = {1};
    return m;
}


TEST(FieldSeriesWriter, BodiesAndCollectionsListTheSnapshotsInOrder) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 8));
    const fem::Mesh mesh = oneTet();
    BodyField piston{&mesh, Eigen::Vector3d(0.0, 0.0, -0.02), Eigen::VectorXd::LinSpaced(12, -1e-5, 1e-5),
                     Eigen::VectorXd::LinSpaced(12, 0.0, 1e-6)};
    BodyField liner{&mesh, Eigen::Vector3d(0.0, 0.0, 0.1), Eigen::VectorXd::Zero(12), Eigen::VectorXd()};

    FieldSeriesWriter w(dir.string());
    const double times[] = {10.0, 10.25, 370.5, 729.75};
    for (int s = 0; s < 4; ++s) {
        piston.origin.z() = -0.02 - 0.001 * s;
        w.write(at(times[s]), f.film, &piston, s % 2 == 0 ? &liner : nullptr);
    }
    EXPECT_EQ(w.count(), 4);
    EXPECT_FALSE(fs::exists(dir / "film.pvd")) << "the collections wait for commit()";
    w.commit();
    EXPECT_EQ(w.committed(), 4);

    const auto film = readPvd(dir / "film.pvd");
    ASSERT_EQ(film.size(), 4u);
    for (int s = 0; s < 4; ++s) {
        EXPECT_EQ(film[std::size_t(s)].time, times[s]);
        EXPECT_EQ(film[std::size_t(s)].file, "vtk/film_00000" + std::to_string(s) + ".vts");
        EXPECT_TRUE(fs::exists(dir / film[std::size_t(s)].file));
    }
    const auto pistonPvd = readPvd(dir / "piston.pvd");
    ASSERT_EQ(pistonPvd.size(), 4u);
    EXPECT_EQ(pistonPvd[3].file, "vtk/piston_000003.vtu");
    const auto linerPvd = readPvd(dir / "liner.pvd");
    ASSERT_EQ(linerPvd.size(), 2u);  // only the snapshots that had a liner
    EXPECT_EQ(linerPvd[0].time, 10.0);
    EXPECT_EQ(linerPvd[1].time, 370.5);
    EXPECT_EQ(linerPvd[1].file, "vtk/liner_000002.vtu");
    for (const auto& e : fs::directory_iterator(dir / "vtk")) EXPECT_NE(e.path().extension(), ".tmp");
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".tmp");

    // The last piston snapshot: points in the cylinder frame, both displacement vectors.
    const auto vtu = readVtu(dir / "vtk" / "piston_000003.vtu");
    ASSERT_EQ(vtu->GetNumberOfPoints(), 4);
    EXPECT_EQ(vtu->GetNumberOfCells(), 1);
    for (vtkIdType n = 0; n < 4; ++n) {
        double x[3];
        vtu->GetPoint(n, x);
        for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(x[c], mesh.nodes(c, n) + piston.origin(c));
        auto* u = vtu->GetPointData()->GetArray("displacement_m");
        auto* e = vtu->GetPointData()->GetArray("elastic_displacement_m");
        ASSERT_NE(u, nullptr);
        ASSERT_NE(e, nullptr);
        ASSERT_EQ(u->GetNumberOfComponents(), 3);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(u->GetComponent(n, c), piston.displacement(3 * n + c));
            EXPECT_EQ(e->GetComponent(n, c), piston.elastic(3 * n + c));
        }
    }
    const auto linerVtu = readVtu(dir / "vtk" / "liner_000002.vtu");
    EXPECT_NE(linerVtu->GetPointData()->GetArray("displacement_m"), nullptr);
    EXPECT_EQ(linerVtu->GetPointData()->GetArray("elastic_displacement_m"), nullptr);  // not given
    // Field data of the body files: the snapshot's crank angle and cycle (729.75° = cycle 2 at 9.75°).
    const auto last = readVtu(dir / "vtk" / "piston_000003.vtu");
    ASSERT_NE(last->GetFieldData()->GetArray("crank_deg"), nullptr);
    EXPECT_EQ(last->GetFieldData()->GetArray("crank_deg")->GetTuple1(0), 9.75);
    EXPECT_EQ(last->GetFieldData()->GetArray("cycle")->GetTuple1(0), 2.0);
    EXPECT_EQ(last->GetFieldData()->GetArray("TimeValue")->GetTuple1(0), 729.75);
}

// The liner's oil layer: one row per cell on the bore (the first θ column repeated at the seam),
// placed at the liner frame's origin, listed in liner_oil.pvd only for the snapshots that have it.
TEST(FieldSeriesWriter, LinerOilLayerIsASeriesOnTheBore) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 8));
    const std::vector<double> z{-0.05, -0.049, -0.048};
    LinerOilField oil;
    oil.grid = &f.grid;
    oil.origin = Eigen::Vector3d(0.0, 0.0, 0.22);
    oil.z = &z;
    oil.thickness = Eigen::VectorXd::LinSpaced(24, 1e-6, 4e-6);
    FieldSeriesWriter w(dir.string());
    w.write(at(10.0), f.film, nullptr, nullptr, &oil);
    w.write(at(20.0), f.film, nullptr, nullptr);
    w.commit();
    const auto pvd = readPvd(dir / "liner_oil.pvd");
    ASSERT_EQ(pvd.size(), 1u);
    EXPECT_EQ(pvd[0].file, "vtk/liner_oil_000000.vts");
    const auto vts = readVts(dir / pvd[0].file);
    int dims[3];
    vts->GetDimensions(dims);
    EXPECT_EQ(dims[0], 9);
    EXPECT_EQ(dims[1], 3);
    auto* t = vts->GetPointData()->GetArray("oil_thickness_m");
    ASSERT_NE(t, nullptr);
    for (int c = 0; c < 3; ++c)
        for (int jj = 0; jj < 9; ++jj) {
            const int j = jj % 8;
            double x[3];
            vts->GetPoint(vtkIdType(c) * 9 + jj, x);
            EXPECT_NEAR(x[0], 0.043 * std::cos(f.grid.theta(j)), 1e-15);
            EXPECT_NEAR(x[1], 0.043 * std::sin(f.grid.theta(j)), 1e-15);
            EXPECT_DOUBLE_EQ(x[2], 0.22 + z[std::size_t(c)]);
            EXPECT_EQ(t->GetTuple1(vtkIdType(c) * 9 + jj), oil.thickness[c * 8 + j]);
        }
    EXPECT_EQ(vts->GetFieldData()->GetArray("crank_deg")->GetTuple1(0), 10.0);
    oil.thickness.resize(5);
    EXPECT_THAT([&] { w.write(at(30.0), f.film, nullptr, nullptr, &oil); },
                ThrowsMessage<std::runtime_error>(HasSubstr("expected 3 cells × 8 columns")));
    oil.thickness = Eigen::VectorXd::Zero(24);
    oil.thickness[9] = std::nan("");
    EXPECT_THAT([&] { w.write(at(30.0), f.film, nullptr, nullptr, &oil); },
                ThrowsMessage<std::runtime_error>(HasSubstr("cell 1, column 1")));
}

TEST(FieldSeriesWriter, BadSnapshotsAreRefusedBeforeAnyFileIsWritten) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 8));
    const fem::Mesh mesh = oneTet();
    BodyField piston{&mesh, Eigen::Vector3d::Zero(), Eigen::VectorXd::Zero(12), Eigen::VectorXd()};
    FieldSeriesWriter w(dir.string());

    FilmField bad = f.film;
    bad.pressure(f.grid.index(3, 5)) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { w.write(at(1.0), bad, &piston, nullptr); },
                ThrowsMessage<std::runtime_error>(
                    AllOf(HasSubstr("'pressure'"), HasSubstr("axial row 3"), HasSubstr("θ column 5"))));
    bad = f.film;
    bad.filmThickness.resize(7);
    EXPECT_THAT([&] { w.write(at(1.0), bad, &piston, nullptr); },
                ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("'filmThickness'"), HasSubstr("7 values"))));
    bad = f.film;
    bad.cavitation(0) = std::numeric_limits<double>::infinity();
    EXPECT_THAT([&] { w.write(at(1.0), bad, &piston, nullptr); },
                ThrowsMessage<std::runtime_error>(HasSubstr("'cavitation'")));
    BodyField badBody = piston;
    badBody.displacement(7) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { w.write(at(1.0), f.film, &badBody, nullptr); },
                ThrowsMessage<std::runtime_error>(
                    AllOf(HasSubstr("piston"), HasSubstr("'displacement'"), HasSubstr("Gmsh tag 13"))));
    EXPECT_THAT([&] { w.write(at(std::numeric_limits<double>::quiet_NaN()), f.film, nullptr, nullptr); },
                ThrowsMessage<std::runtime_error>(HasSubstr("not finite")));
    EXPECT_EQ(w.count(), 0);
    EXPECT_TRUE(fs::is_empty(dir / "vtk"));
    EXPECT_FALSE(fs::exists(dir / "film.pvd"));

    w.write(at(5.0), f.film, &piston, nullptr);
    EXPECT_THAT([&] { w.write(at(5.0), f.film, &piston, nullptr); },
                ThrowsMessage<std::runtime_error>(HasSubstr("strictly increasing")));
    w.commit();
    EXPECT_EQ(readPvd(dir / "film.pvd").size(), 1u);
}

// One series per cycle: commit() lists the snapshots since the last commit and deletes the files
// of the series it replaces; discard() deletes the unfinished ones and keeps the series. The
// time axis starts again with each series.
TEST(FieldSeriesWriter, EachCommitReplacesTheSeriesAndDiscardKeepsIt) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 8));
    const fem::Mesh mesh = oneTet();
    BodyField piston{&mesh, Eigen::Vector3d::Zero(), Eigen::VectorXd::Zero(12), Eigen::VectorXd()};
    FieldSeriesWriter w(dir.string());
    for (double t : {0.0, 360.0, 720.0}) w.write(at(t), f.film, &piston, nullptr);  // cycle 1
    w.commit();
    for (double t : {0.0, 360.0, 720.0}) w.write(at(t), f.film, &piston, nullptr);  // cycle 2
    EXPECT_EQ(readPvd(dir / "film.pvd")[0].file, "vtk/film_000000.vts") << "cycle 1 until cycle 2 commits";
    w.commit();
    const auto film = readPvd(dir / "film.pvd"), body = readPvd(dir / "piston.pvd");
    ASSERT_EQ(film.size(), 3u);
    ASSERT_EQ(body.size(), 3u);
    EXPECT_EQ(film[0].file, "vtk/film_000003.vts");
    EXPECT_EQ(body[2].file, "vtk/piston_000005.vtu");
    for (int k = 0; k < 3; ++k) {
        EXPECT_FALSE(fs::exists(dir / ("vtk/film_00000" + std::to_string(k) + ".vts"))) << k;
        EXPECT_FALSE(fs::exists(dir / ("vtk/piston_00000" + std::to_string(k) + ".vtu"))) << k;
    }
    w.write(at(0.0), f.film, &piston, nullptr);  // an unfinished cycle 3
    w.discard();
    EXPECT_FALSE(fs::exists(dir / "vtk/film_000006.vts"));
    EXPECT_EQ(readPvd(dir / "film.pvd").size(), 3u);
    for (const auto& e : film) EXPECT_TRUE(fs::exists(dir / e.file)) << e.file;
}

// A run into a directory where an earlier, finer run wrote its series: the first commit removes
// the earlier run's series files that the new series does not name (and leaves other files), and
// the earlier .pvd of a series the new run does not write; until then the earlier series stays
// whole (a run killed before its first commit leaves it valid).
TEST(FieldSeriesWriter, TheFirstCommitRemovesWhatAnEarlierRunLeft) {
    const auto dir = test::scratchDir();
    FilmFixture f(lube::FilmGrid::fullCircumference(0.043, kAxial, 8));
    const fem::Mesh mesh = oneTet();
    BodyField piston{&mesh, Eigen::Vector3d::Zero(), Eigen::VectorXd::Zero(12), Eigen::VectorXd()};
    {
        FieldSeriesWriter earlier(dir.string());  // five film and piston snapshots
        for (double t : {0.0, 180.0, 360.0, 540.0, 720.0}) earlier.write(at(t), f.film, &piston, nullptr);
        earlier.commit();
    }
    test::writeFile(dir / "vtk" / "notes.txt", "kept");
    test::writeFile(dir / "vtk" / "film_12.vts", "not a series file name: kept");
    FieldSeriesWriter w(dir.string());  // two film snapshots, no piston
    for (double t : {0.0, 720.0}) w.write(at(t), f.film, nullptr, nullptr);
    EXPECT_EQ(readPvd(dir / "film.pvd").size(), 5u) << "the earlier series until the first commit";
    for (const auto& e : readPvd(dir / "film.pvd")) EXPECT_TRUE(fs::exists(dir / e.file)) << e.file;
    w.commit();
    const auto film = readPvd(dir / "film.pvd");
    ASSERT_EQ(film.size(), 2u);
    for (const auto& e : film) EXPECT_TRUE(fs::exists(dir / e.file)) << e.file;
    std::size_t seriesFiles = 0;
    for (const auto& entry : fs::directory_iterator(dir / "vtk"))
        seriesFiles += entry.path().extension() == ".vts" || entry.path().extension() == ".vtu";
    EXPECT_EQ(seriesFiles, 3u) << "the new run's two film files and film_12.vts";
    EXPECT_FALSE(fs::exists(dir / "piston.pvd"));
    EXPECT_TRUE(fs::exists(dir / "vtk" / "notes.txt"));
    EXPECT_TRUE(fs::exists(dir / "vtk" / "film_12.vts"));
}

// Mode shapes (ModeShapeExport): LZ4 files that VTK reads back; written once — an export of the
// same data into the same directory keeps the files (same modification time), changed shapes or
// a missing file rewrite them.
TEST(ModeShapeExport, WrittenOnceAndRewrittenWhenTheDataChanges) {
    const auto dir = test::scratchDir() / "modes";
    const fem::Mesh mesh = oneTet();
    Eigen::MatrixXd shapes(12, 3);
    shapes.setRandom();
    const Eigen::VectorXd freq = Eigen::VectorXd::LinSpaced(3, 100.0, 300.0);
    bool reused = true;
    const auto files = writeModeShapes(dir.string(), mesh, shapes, freq, Eigen::VectorXd(), &reused);
    EXPECT_FALSE(reused);
    ASSERT_EQ(files.size(), 4u);
    EXPECT_EQ(files.front(), "mode_001.vtu");
    EXPECT_EQ(files.back(), "modes.pvd");
    EXPECT_TRUE(fs::exists(dir / "modes.fingerprint"));
    EXPECT_EQ(slurp(dir / "modes.fingerprint"), modeShapeFingerprint(mesh, shapes, freq, Eigen::VectorXd()) + "\n");
    const auto vtu = readVtu(dir / "mode_002.vtu");
    ASSERT_EQ(vtu->GetNumberOfPoints(), 4);
    auto* u = vtu->GetPointData()->GetArray("displacement_m");
    ASSERT_NE(u, nullptr);
    const double scale = u->GetComponent(0, 0) / shapes(0, 1);  // the viewing scale, same for all
    for (vtkIdType n = 0; n < 4; ++n)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(u->GetComponent(n, c), scale * shapes(3 * n + c, 1), 1e-15 * std::abs(scale));
    ASSERT_EQ(readPvd(dir / "modes.pvd").size(), 3u);

    const auto stamp = fs::last_write_time(dir / "mode_001.vtu");
    EXPECT_EQ(writeModeShapes(dir.string(), mesh, shapes, freq, Eigen::VectorXd(), &reused), files);
    EXPECT_TRUE(reused);
    EXPECT_EQ(fs::last_write_time(dir / "mode_001.vtu"), stamp);

    shapes(4, 2) += 1e-3;  // other data: rewritten
    writeModeShapes(dir.string(), mesh, shapes, freq, Eigen::VectorXd(), &reused);
    EXPECT_FALSE(reused);
    EXPECT_EQ(slurp(dir / "modes.fingerprint"), modeShapeFingerprint(mesh, shapes, freq, Eigen::VectorXd()) + "\n");
    fs::remove(dir / "mode_003.vtu");  // a file missing: rewritten
    writeModeShapes(dir.string(), mesh, shapes, freq, Eigen::VectorXd(), &reused);
    EXPECT_FALSE(reused);
    EXPECT_TRUE(fs::exists(dir / "mode_003.vtu"));
    writeModeShapes(dir.string(), mesh, shapes, freq, Eigen::VectorXd(), &reused);
    EXPECT_TRUE(reused);
}

}  // namespace
}  // namespace flexehd::cosim
