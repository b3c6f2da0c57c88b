#include "cosim/io/VtuWriter.hpp"

#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "cosim/io/VtkXmlFile.hpp"


namespace flexehd::cosim {
namespace {

// Gmsh → VTK local node order for the tetrahedra (VTK edges 01 12 20 03 13 23).
constexpr int kTet10ToVtk[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

vtkNew<vtkDoubleArray> makeArray(const std::string& name, const Eigen::MatrixXd& v, const std::string& path) {
    if (!v.allFinite()) throw std::runtime_error("'" + path + "': field '" + name + "' has NaN or Inf values");
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->SetNumberOfComponents(static_cast<int>(v.rows()));
    a->SetNumberOfTuples(v.cols());
    std::copy(v.data(), v.data() + v.size(), a->GetPointer(0));
    return a;
}

// One block of cells of `perCell` points each (connectivity: cells × perCell point indices) with
// point fields, field data, written atomically.
void writeCells(const std::string& path, const Eigen::Matrix3Xd& coordinates, int cellType, int perCell,
                const std::vector<vtkIdType>& connectivityIds, const std::vector<PointField>& fields,
                const std::vector<FieldValue>& fieldData, VtuCompression compression) {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(coordinates.cols());
    for (Eigen::Index i = 0; i < coordinates.cols(); ++i)
        points->SetPoint(i, coordinates(0, i), coordinates(1, i), coordinates(2, i));
    grid->SetPoints(points);
    const auto cellCount = static_cast<vtkIdType>(connectivityIds.size()) / perCell;
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(cellCount + 1);
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(connectivityIds.size()));
    for (vtkIdType e = 0; e <= cellCount; ++e) offsets->SetValue(e, e * perCell);
    for (std::size_t k = 0; k < connectivityIds.size(); ++k) connectivity->SetValue(static_cast<vtkIdType>(k), connectivityIds[k]);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    grid->SetCells(cellType, cells);

    for (const auto& f : fields) {
        if (f.values.cols() != coordinates.cols())
            throw std::runtime_error("'" + path + "': field '" + f.name + "' has " +
                                     std::to_string(f.values.cols()) + " values, mesh has " +
                                     std::to_string(coordinates.cols()) + " nodes");
        grid->GetPointData()->AddArray(makeArray(f.name, f.values, path));
    }
    for (const auto& d : fieldData)
        grid->GetFieldData()->AddArray(makeArray(d.name, Eigen::MatrixXd::Constant(1, 1, d.value), path));

    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary
    writer->SetHeaderTypeToUInt64();
    if (compression == VtuCompression::LZ4)
        writer->SetCompressorTypeToLZ4();
    else if (compression == VtuCompression::None)
        writer->SetCompressorTypeToNone();
    writeVtkXmlAtomically(path, *writer);
}

}  // namespace

void writeVtu(const std::string& path, const fem::Mesh& mesh, const std::vector<PointField>& fields,
              const std::vector<FieldValue>& fieldData, VtuCompression compression) {
    const bool quadratic = mesh.volume.type == fem::ElementType::Tet10;
    const int npe = quadratic ? 10 : 4;
    std::vector<vtkIdType> connectivity(static_cast<std::size_t>(mesh.volume.size()) * npe);
    for (fem::Index e = 0; e < mesh.volume.size(); ++e)
        for (int a = 0; a < npe; ++a)
            connectivity[static_cast<std::size_t>(e) * npe + a] = mesh.volume.nodes(quadratic ? kTet10ToVtk[a] : a, e);
    writeCells(path, mesh.nodes, quadratic ? VTK_QUADRATIC_TETRA : VTK_TETRA, npe, connectivity, fields, fieldData,
               compression);
}

void writeTriangleSurfaceVtu(const std::string& path, const Eigen::Matrix3Xd& points, const std::vector<int>& triangles,
                             const std::vector<PointField>& fields, const std::vector<FieldValue>& fieldData) {
    if (triangles.size() % 3 != 0) throw std::runtime_error("'" + path + "': triangles are not 3 point indices each");
    std::vector<vtkIdType> connectivity(triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        if (triangles[k] < 0 || triangles[k] >= points.cols())
            throw std::runtime_error("'" + path + "': triangle point " + std::to_string(triangles[k]) + " of " +
                                     std::to_string(points.cols()) + " points");
        connectivity[k] = triangles[k];
    }
    writeCells(path, points, VTK_TRIANGLE, 3, connectivity, fields, fieldData, VtuCompression::LZ4);
}

}  // namespace flexehd::cosim
