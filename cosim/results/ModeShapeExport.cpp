#include "cosim/results/ModeShapeExport.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "cosim/io/PvdWriter.hpp"
#include "cosim/io/VtuWriter.hpp"
#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

constexpr int kFormatVersion = 2;  // 2: LZ4 blocks; bump when the files' content changes

// 64-bit FNV-1a over 8-byte words (a fingerprint, not a cryptographic hash).
struct Hash {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    void word(std::uint64_t w) { h = (h ^ w) * 0x100000001b3ULL; }
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        word(n);
        std::size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            std::uint64_t w;
            std::memcpy(&w, p + i, 8);
            word(w);
        }
        std::uint64_t tail = 0;
        if (n > i) std::memcpy(&tail, p + i, n - i);  // an empty field's data() may be null
        word(tail);
    }
    template <typename M>
    void matrix(const M& m) {
        word(std::uint64_t(m.rows()));
        word(std::uint64_t(m.cols()));
        bytes(m.data(), sizeof(typename M::Scalar) * std::size_t(m.size()));
    }
};

std::string readFile(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

}  // namespace

std::string modeShapeFingerprint(const fem::Mesh& mesh, const Eigen::MatrixXd& shapes,
                                 const Eigen::VectorXd& frequenciesHz, const Eigen::VectorXd& eigenvalues) {
    Hash h;
    h.word(kFormatVersion);
    h.matrix(mesh.nodes);
    h.word(std::uint64_t(mesh.volume.type));
    h.matrix(mesh.volume.nodes);
    h.matrix(shapes);
    h.matrix(frequenciesHz);
    h.matrix(eigenvalues);
    return fmt::format("{:016x}", h.h);
}

// Shapes are scaled so that the largest displacement is 5 % of the model's bounding-box
// diagonal (a readable Warp By Vector at scale 1); the factor back to the stored shape is
// kept with each file.
std::vector<std::string> writeModeShapes(const std::string& directory, const fem::Mesh& mesh,
                                         const Eigen::MatrixXd& shapes, const Eigen::VectorXd& frequenciesHz,
                                         const Eigen::VectorXd& eigenvalues, bool* reused) {
    if (shapes.rows() != 3 * Eigen::Index(mesh.numNodes()) || frequenciesHz.size() != shapes.cols())
        throw std::invalid_argument("mode shapes do not match the mesh (" + std::to_string(shapes.rows()) +
                                    " rows for " + std::to_string(mesh.numNodes()) + " nodes)");
    fs::create_directories(directory);
    fem::removeStaleTemporaries(directory);
    const fs::path dir(directory);
    std::vector<std::string> files;
    for (Eigen::Index k = 0; k < shapes.cols(); ++k) files.push_back(fmt::format("mode_{:03d}.vtu", k + 1));
    files.push_back("modes.pvd");

    // The same data exported before (every file present): keep it.
    const std::string fingerprint = modeShapeFingerprint(mesh, shapes, frequenciesHz, eigenvalues);
    const fs::path stamp = dir / "modes.fingerprint";
    bool same = fs::exists(stamp) && readFile(stamp) == fingerprint + "\n";
    for (const std::string& f : files) same = same && fs::exists(dir / f);
    if (reused) *reused = same;
    if (same) return files;
    std::error_code ec;
    fs::remove(stamp, ec);  // the files below no longer match an old stamp until it is rewritten

    const double diagonal = (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm();
    PvdCollection pvd;
    for (Eigen::Index k = 0; k < shapes.cols(); ++k) {
        Eigen::MatrixXd u = Eigen::Map<const Eigen::MatrixXd>(shapes.col(k).data(), 3, mesh.numNodes());
        const double umax = u.colwise().norm().maxCoeff();
        const double scale = umax > 0.0 ? 0.05 * diagonal / umax : 1.0;
        u *= scale;
        const std::string& name = files[std::size_t(k)];
        std::vector<FieldValue> data{{"mode", double(k + 1)}, {"frequency_hz", frequenciesHz(k)}};
        if (eigenvalues.size() == shapes.cols()) data.push_back({"eigenvalue_rad2_per_s2", eigenvalues(k)});
        data.push_back({"mass_normalisation_factor", 1.0 / scale});
        writeVtu((dir / name).string(), mesh, {{"displacement_m", u}}, data, VtuCompression::LZ4);
        pvd.add(double(k + 1), name);
    }
    pvd.write((dir / "modes.pvd").string());
    fem::writeTextAtomically(stamp.string(), fingerprint + "\n");
    return files;
}

}  // namespace flexehd::cosim
