#include "fem/Mesh.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/LU>

#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

namespace flexehd::fem {

Eigen::Matrix3Xd referenceNodes(ElementType t) {
    Eigen::Matrix3Xd xi(3, nodesPerElement(t));
    const int nv = dimension(t) + 1;
    xi.leftCols(nv).setZero();
    for (int v = 1; v < nv; ++v) xi(v - 1, v) = 1.0;
    if (t == ElementType::Tet10)
        for (int e = 0; e < 6; ++e)
            xi.col(4 + e) = 0.5 * (xi.col(kTet10Edges[e][0]) + xi.col(kTet10Edges[e][1]));
    if (t == ElementType::Tri6)
        for (int e = 0; e < 3; ++e)
            xi.col(3 + e) = 0.5 * (xi.col(kTri6Edges[e][0]) + xi.col(kTri6Edges[e][1]));
    return xi;
}

const PhysicalGroup& Mesh::group(const std::string& name) const {
    auto it = groups.find(name);
    if (it == groups.end())
        throw std::invalid_argument("mesh '" + source + "' has no physical group '" + name +
                                    "'; available: " + groupNames());
    return it->second;
}

std::vector<Index> Mesh::groupNodes(const std::string& name) const {
    const PhysicalGroup& g = group(name);
    const ElementBlock& block = g.dim == 3 ? volume : surface;
    std::vector<Index> out;
    out.reserve(g.elements.size() * block.nodes.rows());
    for (Index e : g.elements)
        for (Index a = 0; a < block.nodes.rows(); ++a) out.push_back(block.nodes(a, e));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::string Mesh::groupNames() const {
    if (groups.empty()) return "(none)";
    std::string s;
    for (const auto& [n, g] : groups) {
        if (!s.empty()) s += ", ";
        s += n + (g.dim == 3 ? " (volume)" : " (surface)");
    }
    return s;
}

namespace {

template <ElementType T>
double volumeOf(const Mesh& m) {
    using S = Shape<T>;
    const auto& rule = tetrahedronRule(T == ElementType::Tet4 ? 1 : 2);
    double v = 0.0;
    Eigen::Matrix<double, 3, S::kNodes> X;
    for (Index e = 0; e < m.volume.size(); ++e) {
        for (int a = 0; a < S::kNodes; ++a) X.col(a) = m.nodes.col(m.volume.nodes(a, e));
        for (const auto& q : rule) v += q.weight * (X * S::dN(q.xi)).determinant();
    }
    return v;
}

// detJ at the nodes and at the degree-2 quadrature points: for TET10, detJ is a cubic
// polynomial, so sampling these 14 points catches inverted curved elements in practice.
template <ElementType T>
void checkShapes(const Mesh& m) {
    using S = Shape<T>;
    Eigen::Matrix3Xd samples = referenceNodes(T);
    if (T == ElementType::Tet10) {
        const auto& rule = tetrahedronRule(2);
        Eigen::Matrix3Xd all(3, samples.cols() + static_cast<Index>(rule.size()));
        all.leftCols(samples.cols()) = samples;
        for (std::size_t q = 0; q < rule.size(); ++q) all.col(samples.cols() + q) = rule[q].xi;
        samples = all;
    }
    std::vector<typename S::Gradients> grads;
    for (Index s = 0; s < samples.cols(); ++s) grads.push_back(S::dN(samples.col(s)));
    Eigen::Matrix<double, 3, S::kNodes> X;
    for (Index e = 0; e < m.volume.size(); ++e) {
        for (int a = 0; a < S::kNodes; ++a) X.col(a) = m.nodes.col(m.volume.nodes(a, e));
        double h = 0.0;  // longest vertex-to-vertex edge
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) h = std::max(h, (X.col(i) - X.col(j)).norm());
        double detMin = std::numeric_limits<double>::infinity();
        for (const auto& g : grads) detMin = std::min(detMin, (X * g).determinant());
        if (detMin < 0.0 || detMin <= 1e-10 * h * h * h) {
            std::ostringstream msg;
            msg << "mesh '" << m.source << "': " << (detMin < 0.0 ? "inverted" : "degenerate")
                << " " << name(T) << " element " << m.volume.tags[e]
                << " (minimum Jacobian determinant " << detMin << ", edge length " << h
                << " m); fix the mesh (e.g. Mesh.HighOrderOptimize for curved elements)";
            throw std::runtime_error(msg.str());
        }
    }
}

}  // namespace

double Mesh::volumeMeasure() const {
    return volume.type == ElementType::Tet4 ? volumeOf<ElementType::Tet4>(*this)
                                            : volumeOf<ElementType::Tet10>(*this);
}

void Mesh::checkElements() const {
    if (volume.type == ElementType::Tet4)
        checkShapes<ElementType::Tet4>(*this);
    else
        checkShapes<ElementType::Tet10>(*this);
}

}  // namespace flexehd::fem
