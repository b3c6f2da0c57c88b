#include "cosim/results/FieldSeriesWriter.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>
#include <vtkUnsignedCharArray.h>

#include "cosim/io/CylinderMapWriter.hpp"
#include "cosim/io/VtuWriter.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

// A film field and its name in the .vts (unit suffix as in history.csv).
struct NamedFilmField {
    const char* what;  // in messages: the FilmField member
    const char* name;  // in the file
    const Eigen::VectorXd* values;
    bool required;
};

std::vector<NamedFilmField> filmFields(const FilmField& f) {
    return {{"pressure", "pressure_pa", &f.pressure, true},
            {"filmThickness", "film_thickness_m", &f.filmThickness, true},
            {"contactPressure", "contact_pressure_pa", &f.contactPressure, false},
            {"shearStress", "shear_stress_pa", &f.shearStress, false},
            {"cavitation", "cavitation_fraction", &f.cavitation, false},
            {"filmFraction", "film_fraction", &f.filmFraction, false}};
}

std::string filmNode(const lube::FilmGrid& g, Eigen::Index k) {
    return fmt::format("node {} (axial row {}, θ column {})", k, g.axialIndex(int(k)), g.thetaIndex(int(k)));
}

void checkFilm(const FilmField& film, double time) {
    if (!film.grid) throw std::runtime_error(fmt::format("film snapshot at time {}: no film grid given", time));
    const lube::FilmGrid& g = *film.grid;
    if (!film.origin.allFinite())
        throw std::runtime_error(fmt::format("film snapshot at time {}: origin is not finite", time));
    for (const auto& f : filmFields(film)) {
        const Eigen::VectorXd& v = *f.values;
        if (v.size() == 0 && !f.required) continue;
        if (v.size() != g.size())
            throw std::runtime_error(fmt::format("film snapshot at time {}: field '{}' has {} values, the grid has {} nodes",
                                                 time, f.what, v.size(), g.size()));
        for (Eigen::Index k = 0; k < v.size(); ++k)
            if (!std::isfinite(v(k)))
                throw std::runtime_error(fmt::format("film snapshot at time {}: field '{}' is {} at {}", time, f.what,
                                                     v(k), filmNode(g, k)));
    }
}

void checkBody(const char* body, const BodyField& b, double time) {
    if (!b.mesh) throw std::runtime_error(fmt::format("{} snapshot at time {}: no mesh given", body, time));
    const fem::Mesh& mesh = *b.mesh;
    if (!b.origin.allFinite())
        throw std::runtime_error(fmt::format("{} snapshot at time {}: origin is not finite", body, time));
    const std::pair<const char*, const Eigen::VectorXd*> fields[] = {{"displacement", &b.displacement},
                                                                     {"elastic", &b.elastic}};
    for (const auto& [what, v] : fields) {
        if (v->size() == 0 && v == &b.elastic) continue;
        if (v->size() != 3 * Eigen::Index(mesh.numNodes()))
            throw std::runtime_error(fmt::format("{} snapshot at time {}: field '{}' has {} values, expected 3 × {} nodes",
                                                 body, time, what, v->size(), mesh.numNodes()));
        for (Eigen::Index k = 0; k < v->size(); ++k)
            if (!std::isfinite((*v)(k))) {
                const Eigen::Index node = k / 3;
                const std::size_t tag = std::size_t(node) < mesh.nodeTags.size() ? mesh.nodeTags[std::size_t(node)] : 0;
                throw std::runtime_error(fmt::format("{} snapshot at time {}: field '{}' is {} at node {} (Gmsh tag {}), "
                                                     "component {}",
                                                     body, time, what, (*v)(k), node, tag, "xyz"[k % 3]));
            }
    }
}

vtkNew<vtkDoubleArray> scalarArray(const char* name, vtkIdType count) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(1);
    a->SetNumberOfTuples(count);
    return a;
}

// The film grid as a structured grid nx × nAxial × 1, x = θ (fastest), y = axial. On a periodic
// grid the first θ column is repeated as column nθ so that ParaView draws a closed cylinder.
std::vector<FieldValue> fieldData(const SnapshotTime& at) {
    return {{"TimeValue", at.time}, {"crank_deg", at.crankDeg}, {"cycle", double(at.cycle)}};
}

void writeFilm(const std::string& path, const FilmField& film, const SnapshotTime& at) {
    const lube::FilmGrid& g = *film.grid;
    const int nTheta = g.nTheta(), nAxial = g.nAxial();
    const int nx = nTheta + (g.periodic() ? 1 : 0);
    const vtkIdType count = vtkIdType(nx) * nAxial;

    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(nx, nAxial, 1);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(count);
    std::vector<double> cosT(static_cast<std::size_t>(nTheta)), sinT(static_cast<std::size_t>(nTheta));
    for (int j = 0; j < nTheta; ++j) {
        cosT[std::size_t(j)] = std::cos(g.theta(j));
        sinT[std::size_t(j)] = std::sin(g.theta(j));
    }
    const double R = g.radius();
    for (int i = 0; i < nAxial; ++i)
        for (int jj = 0; jj < nx; ++jj) {
            const std::size_t j = std::size_t(jj % nTheta);
            points->SetPoint(vtkIdType(i) * nx + jj, film.origin.x() + R * cosT[j], film.origin.y() + R * sinT[j],
                             film.origin.z() + g.z(i));
        }
    grid->SetPoints(points);

    for (const auto& f : filmFields(film)) {
        if (f.values->size() == 0) continue;
        auto a = scalarArray(f.name, count);
        for (int i = 0; i < nAxial; ++i)
            for (int jj = 0; jj < nx; ++jj) a->SetValue(vtkIdType(i) * nx + jj, (*f.values)(g.index(i, jj % nTheta)));
        grid->GetPointData()->AddArray(a);
    }
    vtkNew<vtkUnsignedCharArray> kind;  // 0 Film, 1 Fixed, 2 Void: Threshold away the masks
    kind->SetName("node_kind");
    kind->SetNumberOfTuples(count);
    for (int i = 0; i < nAxial; ++i)
        for (int jj = 0; jj < nx; ++jj)
            kind->SetValue(vtkIdType(i) * nx + jj, static_cast<unsigned char>(g.kind(g.index(i, jj % nTheta))));
    grid->GetPointData()->AddArray(kind);
    grid->GetPointData()->SetActiveScalars("pressure_pa");

    addFieldValues(*grid, fieldData(at));  // ParaView shows TimeValue when the file is opened alone
    writeStructuredGrid(path, *grid);
}

void checkOil(const LinerOilField& oil, double time) {
    if (!oil.grid || !oil.z)
        throw std::runtime_error(fmt::format("liner oil snapshot at time {}: no grid or cell positions given", time));
    const Eigen::Index expected = Eigen::Index(oil.z->size()) * oil.grid->nTheta();
    if (oil.thickness.size() != expected)
        throw std::runtime_error(fmt::format("liner oil snapshot at time {}: {} thickness values, expected {} cells × {} "
                                             "columns",
                                             time, oil.thickness.size(), oil.z->size(), oil.grid->nTheta()));
    for (Eigen::Index k = 0; k < oil.thickness.size(); ++k)
        if (!std::isfinite(oil.thickness[k]))
            throw std::runtime_error(fmt::format("liner oil snapshot at time {}: thickness is {} at cell {}, column {}",
                                                 time, oil.thickness[k], k / oil.grid->nTheta(), k % oil.grid->nTheta()));
}

// The layer on the liner's bore, in the cylinder frame.
void writeOil(const std::string& path, const LinerOilField& oil, const SnapshotTime& at) {
    const int nt = oil.grid->nTheta();
    writeCylinderMap(path, *oil.grid, *oil.z, oil.origin,
                     {{"oil_thickness_m", [&](int c, int j) { return oil.thickness[Eigen::Index(c) * nt + j]; }}},
                     fieldData(at));
}

void writeBody(const std::string& path, const BodyField& b, const SnapshotTime& at) {
    const fem::Mesh& mesh = *b.mesh;
    fem::Mesh placed;  // the elements of the body, nodes moved into the cylinder frame
    placed.nodes = mesh.nodes.colwise() + b.origin;
    placed.volume = mesh.volume;
    std::vector<PointField> fields{
        {"displacement_m", Eigen::Map<const Eigen::MatrixXd>(b.displacement.data(), 3, mesh.numNodes())}};
    if (b.elastic.size() != 0)
        fields.push_back({"elastic_displacement_m", Eigen::Map<const Eigen::MatrixXd>(b.elastic.data(), 3, mesh.numNodes())});
    writeVtu(path, placed, fields, fieldData(at), VtuCompression::LZ4);
}

}  // namespace

FieldSeriesWriter::FieldSeriesWriter(std::string directory) : directory_(std::move(directory)) {
    std::error_code ec;
    fs::create_directories(fs::path(directory_) / "vtk", ec);
    if (ec)
        throw std::runtime_error("cannot create '" + (fs::path(directory_) / "vtk").string() + "': " + ec.message());
}

void FieldSeriesWriter::write(const SnapshotTime& at, const FilmField& film, const BodyField* piston,
                              const BodyField* liner, const LinerOilField* oil) {
    const double time = at.time;
    if (!std::isfinite(time) || !std::isfinite(at.crankDeg))
        throw std::runtime_error(fmt::format("snapshot time {} is not finite", time));
    if (!staged_.empty() && !(time > staged_.back().time))
        throw std::runtime_error(fmt::format("snapshot time {} does not follow the previous snapshot's {}: "
                                             "the series must be strictly increasing",
                                             time, staged_.back().time));
    checkFilm(film, time);
    if (piston) checkBody("piston", *piston, time);
    if (liner) checkBody("liner", *liner, time);
    if (oil) checkOil(*oil, time);

    const fs::path dir(directory_);
    const std::string index = fmt::format("{:06d}", count_);
    Staged s{time, "vtk/film_" + index + ".vts", piston ? "vtk/piston_" + index + ".vtu" : "",
             liner ? "vtk/liner_" + index + ".vtu" : "", oil ? "vtk/liner_oil_" + index + ".vts" : ""};
    writeFilm((dir / s.film).string(), film, at);
    if (piston) writeBody((dir / s.piston).string(), *piston, at);
    if (liner) writeBody((dir / s.liner).string(), *liner, at);
    if (oil) writeOil((dir / s.oil).string(), *oil, at);
    staged_.push_back(std::move(s));
    ++count_;
}

void FieldSeriesWriter::commit() {
    const fs::path dir(directory_);
    PvdCollection film, piston, liner, oil;
    std::vector<std::string> files;
    for (const Staged& s : staged_) {
        film.add(s.time, s.film);
        files.push_back(s.film);
        if (!s.piston.empty()) {
            piston.add(s.time, s.piston);
            files.push_back(s.piston);
        }
        if (!s.liner.empty()) {
            liner.add(s.time, s.liner);
            files.push_back(s.liner);
        }
        if (!s.oil.empty()) {
            oil.add(s.time, s.oil);
            files.push_back(s.oil);
        }
    }
    const bool anyPiston = std::any_of(staged_.begin(), staged_.end(), [](const Staged& s) { return !s.piston.empty(); });
    const bool anyLiner = std::any_of(staged_.begin(), staged_.end(), [](const Staged& s) { return !s.liner.empty(); });
    if (!staged_.empty()) film.write((dir / "film.pvd").string());
    if (anyPiston) piston.write((dir / "piston.pvd").string());
    if (anyLiner) liner.write((dir / "liner.pvd").string());
    if (std::any_of(staged_.begin(), staged_.end(), [](const Staged& s) { return !s.oil.empty(); }))
        oil.write((dir / "liner_oil.pvd").string());
    if (!earlierRunRemoved_) {
        removeEarlierRun(files);
        earlierRunRemoved_ = true;
    }
    // The collections no longer name the previous series: its files go.
    std::error_code ec;
    for (const std::string& f : committedFiles_)
        if (std::find(files.begin(), files.end(), f) == files.end()) fs::remove(dir / f, ec);
    if (!staged_.empty()) {
        committedFiles_ = std::move(files);
        committedCount_ = int(staged_.size());
    }
    staged_.clear();
}

namespace {

// The series a file of vtk/ belongs to ("film", "piston", "liner", "liner_oil": <series>_NNNNNN
// .vts or .vtu), or "" for any other file.
std::string seriesOf(const std::string& name) {
    if (name.size() < 12) return "";
    const std::string ext = name.substr(name.size() - 4), digits = name.substr(name.size() - 10, 6);
    if ((ext != ".vts" && ext != ".vtu") || name[name.size() - 11] != '_' ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return "";
    const std::string series = name.substr(0, name.size() - 11);
    for (const char* known : {"film", "piston", "liner", "liner_oil"})
        if (series == known) return series;
    return "";
}

}  // namespace

void FieldSeriesWriter::removeEarlierRun(const std::vector<std::string>& files) const {
    const fs::path dir(directory_);
    std::vector<std::string> written;  // the series this run's files belong to
    for (const std::string& f : files) written.push_back(seriesOf(fs::path(f).filename().string()));
    std::error_code ec;
    for (const char* series : {"film", "piston", "liner", "liner_oil"})
        if (std::find(written.begin(), written.end(), series) == written.end())
            fs::remove(dir / (std::string(series) + ".pvd"), ec);
    std::error_code listing;
    for (fs::directory_iterator it(dir / "vtk", listing), end; !listing && it != end; it.increment(listing)) {
        const std::string name = it->path().filename().string();
        if (!seriesOf(name).empty() && std::find(files.begin(), files.end(), "vtk/" + name) == files.end())
            fs::remove(it->path(), ec);
    }
}

void FieldSeriesWriter::discard() {
    const fs::path dir(directory_);
    std::error_code ec;
    for (const Staged& s : staged_)
        for (const std::string* f : {&s.film, &s.piston, &s.liner, &s.oil})
            if (!f->empty()) fs::remove(dir / *f, ec);
    staged_.clear();
}

}  // namespace flexehd::cosim
