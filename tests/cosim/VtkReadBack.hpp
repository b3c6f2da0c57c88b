#pragma once
// Reading a run's VTK files back in the tests: structured (.vts) and unstructured (.vtu) grids,
// and the entries of a ParaView collection (.pvd).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace flexehd::test {

inline vtkSmartPointer<vtkStructuredGrid> readVts(const std::filesystem::path& p) {
    vtkNew<vtkXMLStructuredGridReader> reader;
    reader->SetFileName(p.c_str());
    reader->Update();
    return vtkSmartPointer<vtkStructuredGrid>(reader->GetOutput());
}

inline vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& p) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(p.c_str());
    reader->Update();
    return vtkSmartPointer<vtkUnstructuredGrid>(reader->GetOutput());
}

/// One data set of a collection: its time step and its file (relative to the .pvd).
struct PvdEntry {
    double time;
    std::string file;
};

inline std::vector<PvdEntry> readPvd(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    EXPECT_THAT(text, ::testing::HasSubstr("type=\"Collection\""));
    const std::regex entry("<DataSet timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*)\"");
    std::vector<PvdEntry> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
        out.push_back({std::stod((*it)[1]), (*it)[2]});
    return out;
}

}  // namespace flexehd::test
