#include "fem/ThermalDeformation.hpp"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Dense>

#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/StaticSolver.hpp"

namespace flexehd::fem {
namespace {

/// Rows of the rigid-body basis for the DOFs of `node`: u = t + ω × (x − c), with ω
/// scaled by the body size L so that all six columns have a similar magnitude.
Eigen::Matrix<double, 3, 6> rigidRows(const Eigen::Vector3d& x, const Eigen::Vector3d& c, double L) {
    const Eigen::Vector3d d = (x - c) / L;
    Eigen::Matrix<double, 3, 6> G;
    G.leftCols<3>().setIdentity();
    G.rightCols<3>() << 0, d(2), -d(1), -d(2), 0, d(0), d(1), -d(0), 0;  // ω × d = −[d]× ω
    return G;
}

}  // namespace

ThermalDeformation solveThermalDeformation(const Mesh& mesh, const ElasticMaterial& material, double expansion,
                                           const Eigen::VectorXd& temperature, double referenceTemperature,
                                           const ThermalSupport& support) {
    const Eigen::Vector3d c = mesh.nodes.rowwise().mean();
    const double L = std::max((mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm(), 1e-300);

    // Held DOFs and the rigid motions they restrain: null space of their rows of R.
    std::vector<Index> heldDofs;
    Eigen::Matrix<double, 6, 6> CtC = Eigen::Matrix<double, 6, 6>::Zero();
    for (const auto& h : support.held)
        for (Index n : mesh.groupNodes(h.group)) {
            const auto G = rigidRows(mesh.nodes.col(n), c, L);
            for (int k = 0; k < 3; ++k)
                if (h.components & (1u << k)) {
                    heldDofs.push_back(3 * n + k);
                    CtC += G.row(k).transpose() * G.row(k);
                }
        }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(CtC);
    const double big = std::max(eig.eigenvalues().maxCoeff(), 1.0);
    std::vector<int> freeCols;
    for (int k = 0; k < 6; ++k)
        if (eig.eigenvalues()(k) < 1e-10 * big) freeCols.push_back(k);
    const int r = int(freeCols.size());
    Eigen::MatrixXd N(6, r);  // free rigid motions, as combinations of the six columns
    for (int k = 0; k < r; ++k) N.col(k) = eig.eigenvectors().col(freeCols[std::size_t(k)]);

    std::vector<Index> refNodes;
    if (support.reference.empty()) {
        refNodes.resize(std::size_t(mesh.numNodes()));
        for (Index n = 0; n < mesh.numNodes(); ++n) refNodes[std::size_t(n)] = n;
    } else {
        refNodes = mesh.groupNodes(support.reference);
    }
    // Reference-group rows of the free rigid motions: (3 × refNodes) × r.
    Eigen::MatrixXd RN(3 * Eigen::Index(refNodes.size()), r);
    for (std::size_t i = 0; i < refNodes.size(); ++i)
        RN.middleRows(3 * Eigen::Index(i), 3) = rigidRows(mesh.nodes.col(refNodes[i]), c, L) * N;

    // Determinate supports: r reference DOFs whose rows of R N are best conditioned.
    std::vector<Index> pinDofs;
    if (r > 0) {
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(RN.transpose());
        if (qr.rank() < r)
            throw std::invalid_argument("thermal deformation: the reference group '" + support.reference +
                                        "' cannot fix the body's free rigid-body motions");
        for (int k = 0; k < r; ++k) {
            const Eigen::Index row = qr.colsPermutation().indices()(k);
            pinDofs.push_back(3 * refNodes[std::size_t(row / 3)] + Index(row % 3));
        }
    }

    const ElasticityAssembler elastic(mesh);
    const SparseMatrix K = elastic.stiffness(material);
    const Eigen::VectorXd f = elastic.thermalLoad(material, expansion, temperature, referenceTemperature);
    DofMap dofs(mesh.numNodes(), 3);
    for (Index d : heldDofs) dofs.constrainDof(d, 0.0);
    for (Index d : pinDofs) dofs.constrainDof(d, 0.0);
    dofs.finalize();
    ThermalDeformation out;
    out.freeRigidModes = r;
    {
        const StaticSolver solver(dofs.reduce(K));
        out.displacement = dofs.expand(solver.solve(dofs.reduceLoad(f, K)));
    }
    // Reactions at the determinate supports: (K u − f) there; zero for a free support.
    const Eigen::VectorXd residual = K.selfadjointView<Eigen::Upper>() * out.displacement - f;
    double react = 0.0;
    for (Index d : pinDofs) react = std::max(react, std::abs(residual(d)));
    out.determinateReaction = react / std::max(f.cwiseAbs().maxCoeff(), 1e-300);

    // Remove the free rigid motions fitted over the reference nodes.
    if (r > 0) {
        Eigen::VectorXd uRef(RN.rows());
        for (std::size_t i = 0; i < refNodes.size(); ++i)
            uRef.segment<3>(3 * Eigen::Index(i)) = out.displacement.segment<3>(3 * refNodes[i]);
        const Eigen::VectorXd a = RN.colPivHouseholderQr().solve(uRef);
        const Eigen::VectorXd rigid = N * a;
        for (Index n = 0; n < mesh.numNodes(); ++n)
            out.displacement.segment<3>(3 * n) -= rigidRows(mesh.nodes.col(n), c, L) * rigid;
    }
    return out;
}

}  // namespace flexehd::fem
