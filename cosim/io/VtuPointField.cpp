#include "cosim/io/VtuPointField.hpp"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <stdexcept>

#include "cosim/io/VtkXmlFile.hpp"

namespace flexehd::cosim {
VtuPointField readVtuPointField(const std::string& path, const std::string& name) {
    if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": no such file or not readable");
    const QuietVtk quiet;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    if (!reader->CanReadFile(path.c_str()))
        throw std::runtime_error(path + ": not a VTK XML unstructured grid (.vtu) file");
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || !grid || !grid->GetPoints() || grid->GetNumberOfPoints() == 0)
        throw std::runtime_error(path + ": cannot read the points of the .vtu file (truncated, or not valid VTK XML?)");
    vtkPointData* pd = grid->GetPointData();
    vtkDataArray* array = pd->GetArray(name.c_str());
    if (!array) {
        std::string have;
        for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
            have += (have.empty() ? "" : ", ") + std::string("'") + (pd->GetArrayName(i) ? pd->GetArrayName(i) : "") + "'";
        throw std::runtime_error(path + ": no point-data array '" + name + "' (the file has " +
                                 (have.empty() ? std::string("none") : have) + ")");
    }
    const vtkIdType n = grid->GetNumberOfPoints();
    const int m = array->GetNumberOfComponents();
    VtuPointField f{Eigen::Matrix3Xd(3, n), Eigen::MatrixXd(m, n)};
    for (vtkIdType j = 0; j < n; ++j) {
        double x[3];
        grid->GetPoint(j, x);
        f.points.col(j) << x[0], x[1], x[2];
        for (int c = 0; c < m; ++c) f.values(c, j) = array->GetComponent(j, c);
    }
    return f;
}

}  // namespace flexehd::cosim
