#pragma once
// A reduced body with a real mesh (the unit cube, TET10) but random, deterministic modal
// data, for the file and command-line tests: the mode shapes and interface motion are
// non-square so that a transposed write or read cannot go unnoticed; the modal mass and
// stiffness are random but, as every body's, symmetric, positive definite and positive
// semi-definite (the reader checks that).
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "../fem/TestData.hpp"
#include "fem/MeshReader.hpp"
#include "modal/ReducedBody.hpp"
#include "modal/ReducedBodyFile.hpp"

namespace flexehd::test {

/// `modes` modes, the first `rigid` of them rigid-body; interfaces: xmin (RBE2), xmax (RBE3).
inline modal::ReducedBody syntheticBody(int modes = 9, int rigid = 6) {
    modal::ReducedBody b;
    b.meshPath = dataPath("cube.geo");
    b.meshHash = modal::fnv1a64File(b.meshPath);
    b.elementOrder = 2;
    b.meshSize = 0.5;
    b.mesh = fem::readMesh(b.meshPath, {2, 0.5});
    b.material = {2.1e11, 0.3, 7850.0};
    b.settings.normalModes = modes - rigid;
    b.settings.cutoffHz = 5000.0;
    b.settings.staticCorrection = {"xmax", "boundary"};
    b.settings.axialOrder = 2;
    b.settings.axialHats = 5;
    b.settings.circumferentialOrder = 3;
    b.settings.dampingRatio = 0.02;
    b.interfaces.push_back({"xmin", modal::InterfaceKind::Rbe2, {0.0, 0.5, 0.5}, b.mesh.groupNodes("xmin")});
    b.interfaces.push_back({"xmax", modal::InterfaceKind::Rbe3, {1.0, 0.5, 0.5}, b.mesh.groupNodes("xmax")});

    std::mt19937_64 rng(20240611);
    std::normal_distribution<double> normal;
    const auto random = [&](Eigen::Index rows, Eigen::Index cols) {
        return Eigen::MatrixXd(Eigen::MatrixXd::NullaryExpr(rows, cols, [&] { return normal(rng); }));
    };
    b.shapes = random(3 * b.mesh.numNodes(), modes);
    const Eigen::MatrixXd dm = random(modes, modes), dk = random(modes, modes);
    b.massMatrix = Eigen::MatrixXd::Identity(modes, modes) + 0.5e-3 * (dm + dm.transpose());
    b.stiffnessMatrix = Eigen::MatrixXd::Zero(modes, modes);
    b.frequenciesHz.resize(modes);
    b.dampingRatios.resize(modes);
    for (int k = 0; k < modes; ++k) {
        const bool isRigid = k < rigid;
        b.frequenciesHz(k) = isRigid ? 1e-4 * std::abs(normal(rng)) : 1000.0 * (k - rigid + 1) + normal(rng);
        b.stiffnessMatrix(k, k) = std::pow(2 * std::numbers::pi * b.frequenciesHz(k), 2);
        b.rigidBody.push_back(isRigid ? 1 : 0);
        b.dampingRatios(k) = isRigid ? 0.0 : 0.02 + 1e-3 * normal(rng);
    }
    // Weak symmetric coupling of the elastic modes: K = Ω (I + 1e-3 S) Ω with Ω = diag(ω), so
    // positive definite on them, and the rigid-body rows zero but for their tiny diagonal.
    for (int i = rigid; i < modes; ++i)
        for (int j = rigid; j < modes; ++j)
            if (i != j)
                b.stiffnessMatrix(i, j) = 0.5e-3 * (dk(i, j) + dk(j, i)) * std::sqrt(b.stiffnessMatrix(i, i)) *
                                          std::sqrt(b.stiffnessMatrix(j, j));
    b.interfaceMotion = random(6 * Eigen::Index(b.interfaces.size()), modes);
    return b;
}

}  // namespace flexehd::test
