#include "cosim/ModeShapeExport.hpp"

#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "cosim/PvdWriter.hpp"
#include "cosim/VtuWriter.hpp"

namespace flexehd::cosim {

// Shapes are scaled so that the largest displacement is 5 % of the model's bounding-box
// diagonal (a readable Warp By Vector at scale 1); the factor back to the stored shape is
// kept with each file.
std::vector<std::string> writeModeShapes(const std::string& directory, const fem::Mesh& mesh,
                                         const Eigen::MatrixXd& shapes, const Eigen::VectorXd& frequenciesHz,
                                         const Eigen::VectorXd& eigenvalues) {
    namespace fs = std::filesystem;
    if (shapes.rows() != 3 * Eigen::Index(mesh.numNodes()) || frequenciesHz.size() != shapes.cols())
        throw std::invalid_argument("mode shapes do not match the mesh (" + std::to_string(shapes.rows()) +
                                    " rows for " + std::to_string(mesh.numNodes()) + " nodes)");
    fs::create_directories(directory);
    const double diagonal = (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm();
    PvdCollection pvd;
    std::vector<std::string> files;
    for (Eigen::Index k = 0; k < shapes.cols(); ++k) {
        Eigen::MatrixXd u = Eigen::Map<const Eigen::MatrixXd>(shapes.col(k).data(), 3, mesh.numNodes());
        const double umax = u.colwise().norm().maxCoeff();
        const double scale = umax > 0.0 ? 0.05 * diagonal / umax : 1.0;
        u *= scale;
        const std::string name = fmt::format("mode_{:03d}.vtu", k + 1);
        std::vector<FieldValue> data{{"mode", double(k + 1)}, {"frequency_hz", frequenciesHz(k)}};
        if (eigenvalues.size() == shapes.cols()) data.push_back({"eigenvalue_rad2_per_s2", eigenvalues(k)});
        data.push_back({"mass_normalisation_factor", 1.0 / scale});
        writeVtu((fs::path(directory) / name).string(), mesh, {{"displacement", u}}, data);
        pvd.add(double(k + 1), name);
        files.push_back(name);
    }
    pvd.write((fs::path(directory) / "modes.pvd").string());
    files.push_back("modes.pvd");
    return files;
}

}  // namespace flexehd::cosim
