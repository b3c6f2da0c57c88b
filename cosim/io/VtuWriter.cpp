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

}  // namespace

void writeVtu(const std::string& path, const fem::Mesh& mesh, const std::vector<PointField>& fields,
              const std::vector<FieldValue>& fieldData, VtuCompression compression) {
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(mesh.numNodes());
    for (fem::Index i = 0; i < mesh.numNodes(); ++i)
        points->SetPoint(i, mesh.nodes(0, i), mesh.nodes(1, i), mesh.nodes(2, i));
    grid->SetPoints(points);

    const bool quadratic = mesh.volume.type == fem::ElementType::Tet10;
    const int npe = quadratic ? 10 : 4;
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(mesh.volume.size() + 1);
    connectivity->SetNumberOfTuples(vtkIdType(mesh.volume.size()) * npe);
    for (fem::Index e = 0; e <= mesh.volume.size(); ++e) offsets->SetValue(e, vtkIdType(e) * npe);
    for (fem::Index e = 0; e < mesh.volume.size(); ++e)
        for (int a = 0; a < npe; ++a)
            connectivity->SetValue(vtkIdType(e) * npe + a, mesh.volume.nodes(quadratic ? kTet10ToVtk[a] : a, e));
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    grid->SetCells(quadratic ? VTK_QUADRATIC_TETRA : VTK_TETRA, cells);

    for (const auto& f : fields) {
        if (f.values.cols() != mesh.numNodes())
            throw std::runtime_error("'" + path + "': field '" + f.name + "' has " +
                                     std::to_string(f.values.cols()) + " values, mesh has " +
                                     std::to_string(mesh.numNodes()) + " nodes");
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

}  // namespace flexehd::cosim
