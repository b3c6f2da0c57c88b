#pragma once
// Shared by the clearance-term tests (bore distortion, thermal.h5, their case keys): the example
// engine on a coarse grid, the liner offsets a run visits, the film change of the clearance
// terms, and a thermal.h5 written with the HDF5 C API.
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cosim/case/EngineCase.hpp"
#include "cosim/clearance/ClearanceTerms.hpp"
#include "cosim/engine/SkirtFilm.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"

namespace flexehd::cosim::test {

namespace fs = std::filesystem;

inline constexpr double kPi = std::numbers::pi;


/// The example engine's geometry on a coarse grid; the skirt panels ±40° about ±x (Void between).
inline EngineCase smallCase() {
    EngineCase c;
    c.engine.bore = 0.086;
    c.engine.stroke = 0.086;
    c.engine.rodLength = 0.1435;
    c.engine.speedRpm = 1000.0;
    c.engine.pinTdcDepth = 0.0335;
    c.piston.mass = 0.3159;
    c.piston.pinMass = 0.1355;
    c.piston.inertia = 2.36e-4;
    c.piston.cgZ = 0.0139;
    c.piston.skirtTop = 0.0108;
    c.piston.skirtBottom = -0.025;
    c.piston.clearance = 50e-6;
    c.piston.skirtHalfAngle = 40.0 * kPi / 180.0;
    c.piston.profile = {{-0.025, 20e-6}, {-0.01, 0.0}, {0.0108, 30e-6}};
    c.grid.axialNodes = 9;
    c.grid.circumferentialNodes = 36;
    c.cylinderPressure = {{0.0, 1.0e5}, {360.0, 1.5e5}, {720.0, 1.0e5}};
    c.lubricant.viscosity = 0.0086;
    c.lubricant.density = 820.0;
    c.output.vtkEveryDeg = 0.0;
    c.time.maxCycles = 1;
    return c;
}

/// Liner offsets of the example crank-slider between TDC and BDC, by hand: the pin height above
/// the crank axis is r cos φ + √(l² − r² sin² φ) (no pin offset), and the liner-frame z of the
/// pin is −pin_tdc_depth − (s_TDC − s(φ)) (EngineSpec::pinTdcDepth).
inline double handOffset(const EngineCase& c, double crankDeg) {
    const double r = 0.5 * c.engine.stroke, l = c.engine.rodLength, phi = crankDeg * kPi / 180.0;
    const double s = r * std::cos(phi) + std::sqrt(l * l - r * r * std::sin(phi) * std::sin(phi));
    return -c.engine.pinTdcDepth - ((r + l) - s);
}

// ---- a thermal.h5 written with the HDF5 C API ----------------------------------------------

struct Group {
    std::string name;  // "piston" or "liner"
    std::vector<double> axial, theta;
    std::function<double(double, double)> u;  // u_r(z, θ)
    bool writeTheta = true;
    std::size_t rowsWritten = 0;  // 0: axial.size()
};

inline void attribute(hid_t file, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    const char* p = value.c_str();
    H5Awrite(a, type, &p);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
}

inline void attribute(hid_t file, const char* name, int value) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(file, name, H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, &value);
    H5Aclose(a);
    H5Sclose(space);
}

inline void dataset(hid_t group, const char* name, const std::vector<double>& v, std::vector<hsize_t> dims) {
    const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    const hid_t d = H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(d);
    H5Sclose(space);
}

inline void writeThermal(const fs::path& path, const std::vector<Group>& groups, const std::string& format = kThermalFormat,
                  int version = kThermalFormatVersion) {
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    attribute(file, "format", format);
    attribute(file, "format_version", version);
    for (const Group& g : groups) {
        const hid_t grp = H5Gcreate2(file, ("/" + g.name).c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        dataset(grp, "axial", g.axial, {g.axial.size()});
        if (g.writeTheta) dataset(grp, "theta", g.theta, {g.theta.size()});
        const std::size_t rows = g.rowsWritten ? g.rowsWritten : g.axial.size();
        std::vector<double> u;
        for (std::size_t i = 0; i < rows; ++i)
            for (double th : g.theta) u.push_back(g.u(g.axial[std::min(i, g.axial.size() - 1)], th));
        dataset(grp, "radial_displacement", u, {rows, g.theta.size()});
        H5Gclose(grp);
    }
    H5Fclose(file);
}

inline std::vector<double> uniformTheta(int n) {
    std::vector<double> t;
    for (int j = 0; j < n; ++j) t.push_back(2.0 * kPi * j / n);
    return t;
}

inline std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(a + (b - a) * i / (n - 1));
    return v;
}

/// Liner offsets the run visits (as PistonSimulation computes them, 0.25° sampling).
inline std::pair<double, double> sweep(const EngineCase& c) {
    double lo = handOffset(c, 0.0), hi = lo;
    for (int k = 1; k <= 1440; ++k) {
        lo = std::min(lo, handOffset(c, 0.25 * k));
        hi = std::max(hi, handOffset(c, 0.25 * k));
    }
    return {lo, hi};
}

/// h_rigid at (e, β) with the clearance terms at the offset, minus h_rigid without them.
inline Eigen::VectorXd change(const EngineCase& c, const SkirtFilm& film, double offset) {
    const auto [lo, hi] = sweep(c);
    const ClearanceTerms terms(c, film.grid(), lo, hi);
    Eigen::VectorXd h0, h1;
    film.rigidThickness(3e-6, 2e-4, h0);
    h1 = h0;
    terms.add(offset, h1);
    return h1 - h0;
}


}  // namespace flexehd::cosim::test
