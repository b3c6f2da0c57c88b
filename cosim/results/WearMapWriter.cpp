// WearMapWriter: the wear-rate maps of skirt and liner as .vts files.
#include "cosim/results/WearMapWriter.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridWriter.h>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {

namespace {

// A map on the cylinder of radius R over the axial positions z and the grid's θ columns (the first
// column repeated on a full circumference, so that ParaView draws it closed); value(i, j) in m/s.
template <class Value>
void writeCylinderMap(const std::string& path, const lube::FilmGrid& g, const std::vector<double>& z, Value value) {
    const int nt = g.nTheta(), nx = nt + (g.periodic() ? 1 : 0), nz = static_cast<int>(z.size());
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(nx, nz, 1);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(vtkIdType(nx) * nz);
    vtkNew<vtkDoubleArray> rate;
    rate->SetName("wear_rate_m_per_h");
    rate->SetNumberOfTuples(vtkIdType(nx) * nz);
    for (int i = 0; i < nz; ++i)
        for (int jj = 0; jj < nx; ++jj) {
            const int j = jj % nt;
            const vtkIdType id = vtkIdType(i) * nx + jj;
            points->SetPoint(id, g.radius() * std::cos(g.theta(j)), g.radius() * std::sin(g.theta(j)), z[std::size_t(i)]);
            rate->SetValue(id, 3600.0 * value(i, j));
        }
    grid->SetPoints(points);
    grid->GetPointData()->AddArray(rate);
    grid->GetPointData()->SetActiveScalars("wear_rate_m_per_h");
    fem::writeAtomically(path, [&](const std::string& tmp) {
        vtkNew<vtkXMLStructuredGridWriter> writer;
        writer->SetFileName(tmp.c_str());
        writer->SetInputData(grid);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        if (writer->Write() != 1) throw std::runtime_error("VTK could not write '" + path + "'");
    });
}

}  // namespace

void writeWearMaps(const std::string& directory, const lube::FilmGrid& g, const ArchardWear& wear) {
    writeCylinderMap(directory + "/wear_piston.vts", g, g.axial(),
                     [&](int i, int j) { return wear.pistonRate()[g.index(i, j)]; });
    std::vector<double> z;
    for (int c = 0; c < wear.linerCells(); ++c) z.push_back(wear.linerCellZ(c));
    writeCylinderMap(directory + "/wear_liner.vts", g, z,
                     [&](int c, int j) { return wear.linerRate()[static_cast<Eigen::Index>(c) * g.nTheta() + j]; });
}

}  // namespace flexehd::cosim
