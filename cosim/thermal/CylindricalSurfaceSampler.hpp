#pragma once
// Samples a nodal displacement field on a (z, θ) table over a cylinder-like surface
// (surface groups of a body whose axis is z), for thermal.h5 (docs/thermal.md §6).
// Each triangle's vertices map to the parameter plane (z, s = R̄ θ), R̄ the mean radius
// of the surface nodes (θ unwrapped across ±π). A table point inside a triangle's image
// takes the triangle's shape-function interpolation at those barycentric coordinates;
// a point outside the surface's image (e.g. between the piston's skirt panels) takes the
// value at the nearest point of the image (constant extrapolation), and is flagged.
// Radial component: u·(cos θ, sin θ, 0), outward positive. A nodal scalar (the temperature)
// is sampled the same way (sampleScalar), and its circumferential mean per axial row gives the
// profile over z of thermal.h5's /piston/ring_belt (axialProfile).
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

/// A nodal scalar (e.g. the temperature, K) on the same (z, θ) table.
struct ScalarSurfaceTable {
    std::vector<double> axial;  ///< n_z, m, increasing
    std::vector<double> theta;  ///< n_θ, rad, 2π j / n_θ
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> values;  ///< n_z × n_θ
    Eigen::Matrix<unsigned char, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> onSurface;  ///< 1 inside the image
};

/// A profile over z: one value per axial row.
struct AxialProfile {
    std::vector<double> axial;   ///< m, increasing
    std::vector<double> values;  ///< one per row
};

/// The mean over θ of each row of `t`: over the row's points on the surface, or over all its
/// points (each the value of its nearest surface point) where none of them is, e.g. in the
/// grooves between the lands.
AxialProfile axialProfile(const ScalarSurfaceTable& t);

class CylindricalSurfaceSampler {
public:
    /// Throws std::invalid_argument naming the group if it is unknown or not a surface.
    CylindricalSurfaceSampler(const fem::Mesh& mesh, const std::vector<std::string>& groups);

    double zMin() const { return zMin_; }
    double zMax() const { return zMax_; }
    /// Radial displacement on nAxial uniform z from zMin to zMax × nTheta uniform θ in [0, 2π).
    SurfaceTable sample(const Eigen::VectorXd& displacement, int nAxial, int nTheta) const;
    /// A nodal scalar (one value per mesh node) on the same table.
    ScalarSurfaceTable sampleScalar(const Eigen::VectorXd& nodal, int nAxial, int nTheta) const;

private:
    struct Triangle {
        fem::Index element;  ///< into mesh.surface
        Eigen::Vector2d p[3];  ///< (z, s) of the vertices
        Eigen::Vector2d lo, hi;
    };
    /// The point of the surface's image nearest (z, θ): its triangle, the shape functions there,
    /// and whether (z, θ) lies in the image.
    struct Location {
        const Triangle* triangle = nullptr;
        Eigen::VectorXd N;
        bool onSurface = false;
    };
    Location locate(double z, double theta) const;
    void checkSize(int nAxial, int nTheta) const;

    const fem::Mesh& mesh_;
    std::vector<Triangle> triangles_;
    double radius_ = 0.0, zMin_ = 0.0, zMax_ = 0.0;
};

}  // namespace flexehd::cosim
