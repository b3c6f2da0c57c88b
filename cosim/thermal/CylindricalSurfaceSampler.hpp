#pragma once
// Samples a nodal displacement field on a (z, θ) table over a cylinder-like surface
// (surface groups of a body whose axis is z), for thermal.h5 (docs/thermal.md §6).
// Each triangle's vertices map to the parameter plane (z, s = R̄ θ), R̄ the mean radius
// of the surface nodes (θ unwrapped across ±π). A table point inside a triangle's image
// takes the triangle's shape-function interpolation at those barycentric coordinates;
// a point outside the surface's image (e.g. between the piston's skirt panels) takes the
// value at the nearest point of the image (constant extrapolation), and is flagged.
// Radial component: u·(cos θ, sin θ, 0), outward positive.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::cosim {

struct SurfaceTable {
    std::vector<double> axial;  ///< n_z, m, increasing
    std::vector<double> theta;  ///< n_θ, rad, 2π j / n_θ
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> radial;  ///< n_z × n_θ, m
    Eigen::Matrix<unsigned char, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> onSurface;  ///< 1 inside the image
    double meanRadius = 0.0;  ///< m
};

class CylindricalSurfaceSampler {
public:
    /// Throws std::invalid_argument naming the group if it is unknown or not a surface.
    CylindricalSurfaceSampler(const fem::Mesh& mesh, const std::vector<std::string>& groups);

    double zMin() const { return zMin_; }
    double zMax() const { return zMax_; }
    /// Radial displacement on nAxial uniform z from zMin to zMax × nTheta uniform θ in [0, 2π).
    SurfaceTable sample(const Eigen::VectorXd& displacement, int nAxial, int nTheta) const;

private:
    struct Triangle {
        fem::Index element;  ///< into mesh.surface
        Eigen::Vector2d p[3];  ///< (z, s) of the vertices
        Eigen::Vector2d lo, hi;
    };
    const fem::Mesh& mesh_;
    std::vector<Triangle> triangles_;
    double radius_ = 0.0, zMin_ = 0.0, zMax_ = 0.0;
};

}  // namespace flexehd::cosim
