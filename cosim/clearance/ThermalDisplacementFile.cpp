#include "cosim/clearance/ThermalDisplacementFile.hpp"

#include "modal/Hdf5Handle.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace flexehd::cosim {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

using Id = modal::Hdf5Handle;
using Quiet = modal::QuietHdf5Errors;

class Reader {
public:
    explicit Reader(std::string path)
        : path_(checked(std::move(path))), file_(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose) {
        if (!file_.valid()) fail("cannot be opened as an HDF5 file");
    }

    /// The path, after checking that it names a readable HDF5 file.
    static std::string checked(std::string path) {
        const auto failFor = [&](const std::string& msg) {
            throw std::runtime_error("thermal-displacement file " + path + ": " + msg);
        };
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) failFor("no such file (make it with `flexehd thermal`)");
        if (std::filesystem::is_directory(path, ec)) failFor("is a directory, not a thermal-displacement file");
        if (H5Fis_hdf5(path.c_str()) <= 0)
            failFor("not an HDF5 file (expected a thermal-displacement file from `flexehd thermal`)");
        return path;
    }

    [[noreturn]] void fail(const std::string& msg) const {
        throw std::runtime_error("thermal-displacement file " + path_ + ": " + msg);
    }
    bool has(const std::string& object) const {
        return H5Lexists(file_.get(), object.c_str(), H5P_DEFAULT) > 0 &&
               H5Oexists_by_name(file_.get(), object.c_str(), H5P_DEFAULT) > 0;
    }

    std::string stringAttribute(const std::string& name) const {
        if (H5Aexists(file_.get(), name.c_str()) <= 0)
            fail(fmt::format("missing root attribute '{}' (expected \"{}\")", name, kThermalFormat));
        const Id a(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
        const Id type(H5Aget_type(a.get()), H5Tclose);
        const Id space(H5Aget_space(a.get()), H5Sclose);
        if (H5Tget_class(type.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1)
            fail(fmt::format("root attribute '{}' must be one string (\"{}\")", name, kThermalFormat));
        if (H5Tis_variable_str(type.get()) > 0) {
            const Id mem(H5Tcopy(H5T_C_S1), H5Tclose);
            H5Tset_size(mem.get(), H5T_VARIABLE);
            H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
            char* p = nullptr;
            if (H5Aread(a.get(), mem.get(), &p) < 0) fail("cannot read root attribute '" + name + "'");
            std::string v = p ? p : "";
            H5free_memory(p);
            return v;
        }
        const std::size_t size = H5Tget_size(type.get());
        std::string buffer(size, '\0');
        if (H5Aread(a.get(), type.get(), buffer.data()) < 0) fail("cannot read root attribute '" + name + "'");
        buffer.erase(std::min(buffer.find('\0'), buffer.find_last_not_of(' ') + 1));
        return buffer;
    }

    bool hasAttribute(const std::string& name) const { return H5Aexists(file_.get(), name.c_str()) > 0; }

    long long integerAttribute(const std::string& name) const {
        if (H5Aexists(file_.get(), name.c_str()) <= 0)
            fail(fmt::format("missing root attribute '{}' (expected the integer {})", name, kThermalFormatVersion));
        const Id a(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
        const Id type(H5Aget_type(a.get()), H5Tclose);
        const Id space(H5Aget_space(a.get()), H5Sclose);
        if (H5Tget_class(type.get()) != H5T_INTEGER || H5Sget_simple_extent_npoints(space.get()) != 1)
            fail(fmt::format("root attribute '{}' must be one integer", name));
        long long v = 0;
        if (H5Aread(a.get(), H5T_NATIVE_LLONG, &v) < 0) fail("cannot read root attribute '" + name + "'");
        return v;
    }

    /// A float dataset of the given rank: its dimensions and values (row-major).
    std::vector<double> dataset(const std::string& object, int rank, std::vector<hsize_t>& dims) const {
        if (!has(object)) fail("missing dataset " + object);
        const Id d(H5Dopen2(file_.get(), object.c_str(), H5P_DEFAULT), H5Dclose);
        if (!d.valid()) fail(object + " is not a dataset");
        const Id type(H5Dget_type(d.get()), H5Tclose);
        if (H5Tget_class(type.get()) != H5T_FLOAT) fail("dataset " + object + " must hold floating-point numbers");
        const Id space(H5Dget_space(d.get()), H5Sclose);
        const int r = H5Sget_simple_extent_ndims(space.get());
        if (r != rank)
            fail(fmt::format("dataset {} must have {} dimension{}, has {}", object, rank, rank == 1 ? "" : "s", r));
        dims.assign(std::size_t(rank), 0);
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        hsize_t n = 1;
        for (hsize_t v : dims) n *= v;
        std::vector<double> values(n);
        if (n > 0 && H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
            fail("cannot read dataset " + object);
        for (hsize_t k = 0; k < n; ++k)
            if (!std::isfinite(values[k]))
                fail(fmt::format("dataset {} holds a non-finite value at index {}", object, k));
        return values;
    }

    ThermalField field(const std::string& group) const {
        ThermalField f;
        f.where = path_ + ":" + group;
        std::vector<hsize_t> dz, dt, du;
        f.axial = dataset(group + "/axial", 1, dz);
        f.theta = dataset(group + "/theta", 1, dt);
        f.radial = dataset(group + "/radial_displacement", 2, du);
        const std::size_t nz = f.axial.size(), nt = f.theta.size();
        if (nz < 2) fail(fmt::format("{}/axial needs at least 2 values, has {}", group, nz));
        for (std::size_t k = 1; k < nz; ++k)
            if (!(f.axial[k] > f.axial[k - 1]))
                fail(fmt::format("{}/axial must be strictly increasing: {:g} m follows {:g} m (index {})", group,
                                 f.axial[k], f.axial[k - 1], k));
        if (nt < 3) fail(fmt::format("{}/theta needs at least 3 values, has {}", group, nt));
        const double step = kTwoPi / double(nt);
        if (f.theta[0] < -1e-12 || f.theta[0] >= step)
            fail(fmt::format("{}/theta must start in [0, 2*pi/n_theta) = [0, {:g}) rad, starts at {:g} rad", group,
                             step, f.theta[0]));
        for (std::size_t j = 0; j < nt; ++j)
            if (std::abs(f.theta[j] - (f.theta[0] + double(j) * step)) > 1e-9)
                fail(
                    fmt::format("{}/theta must be uniform in [0, 2*pi) with spacing 2*pi/{} = {:.10g} rad (periodic, "
                                "without repeating 2*pi); value {} is {:.10g} rad",
                                group, nt, step, j, f.theta[j]));
        if (du[0] != nz || du[1] != nt)
            fail(fmt::format("{}/radial_displacement is {} x {}, expected n_z x n_theta = {} x {} (axial x theta)",
                             group, du[0], du[1], nz, nt));
        return f;
    }

    SurfaceTemperatureProfile profile(const std::string& group) const {
        SurfaceTemperatureProfile p;
        p.where = path_ + ":" + group;
        std::vector<hsize_t> dz, dt;
        p.z = dataset(group + "/z_m", 1, dz);
        p.temperature = dataset(group + "/temperature_k", 1, dt);
        if (p.z.size() < 2) fail(fmt::format("{}/z_m needs at least 2 values, has {}", group, p.z.size()));
        if (p.temperature.size() != p.z.size())
            fail(fmt::format("{}/temperature_k has {} values, {}/z_m {}: expected one temperature per z", group,
                             p.temperature.size(), group, p.z.size()));
        for (std::size_t k = 1; k < p.z.size(); ++k)
            if (!(p.z[k] > p.z[k - 1]))
                fail(fmt::format("{}/z_m must be strictly increasing: {:g} m follows {:g} m (index {})", group, p.z[k],
                                 p.z[k - 1], k));
        for (std::size_t k = 0; k < p.temperature.size(); ++k)
            if (!(p.temperature[k] > 0.0))
                fail(fmt::format("{}/temperature_k must be positive (K), is {:g} at index {}", group,
                                 p.temperature[k], k));
        return p;
    }

private:
    std::string path_;
    Id file_;
};

}  // namespace

double ThermalField::at(double z, double th) const {
    const std::size_t nz = axial.size(), nt = theta.size();
    const double tol = 1e-9;
    if (z < axial.front() - tol || z > axial.back() + tol)
        throw std::out_of_range(fmt::format("{}/axial covers {:g} … {:g} m; z = {:g} m lies outside", where,
                                            axial.front(), axial.back(), z));
    z = std::clamp(z, axial.front(), axial.back());
    std::size_t k = std::size_t(std::upper_bound(axial.begin(), axial.end(), z) - axial.begin());
    k = std::min(std::max<std::size_t>(k, 1), nz - 1) - 1;
    const double s = (z - axial[k]) / (axial[k + 1] - axial[k]);
    // Periodic in θ: column j at θ_0 + j Δ.
    const double step = kTwoPi / double(nt);
    double u = std::fmod(th - theta[0], kTwoPi);
    if (u < 0.0) u += kTwoPi;
    std::size_t j = std::min(std::size_t(u / step), nt - 1);
    const double t = std::clamp(u / step - double(j), 0.0, 1.0);
    const std::size_t j1 = (j + 1) % nt;
    const auto v = [&](std::size_t a, std::size_t b) { return radial[a * nt + b]; };
    return (1.0 - s) * ((1.0 - t) * v(k, j) + t * v(k, j1)) + s * ((1.0 - t) * v(k + 1, j) + t * v(k + 1, j1));
}

double SurfaceTemperatureProfile::mean(double zLow, double zHigh) const {
    const double tol = 1e-9;
    if (!(zLow < zHigh) || zLow < z.front() - tol || zHigh > z.back() + tol)
        throw std::out_of_range(fmt::format("{}/z_m covers {:g} … {:g} m; the range {:g} … {:g} m does not lie within it",
                                            where, z.front(), z.back(), zLow, zHigh));
    zLow = std::max(zLow, z.front());
    zHigh = std::min(zHigh, z.back());
    if (!(zHigh > zLow)) return zLow <= z.front() ? temperature.front() : temperature.back();  // within the tolerance
    const auto at = [&](double x, std::size_t k) {  // on segment [z_k, z_k+1]
        return temperature[k] + (temperature[k + 1] - temperature[k]) * (x - z[k]) / (z[k + 1] - z[k]);
    };
    double integral = 0.0;
    for (std::size_t k = 0; k + 1 < z.size(); ++k) {
        const double a = std::max(zLow, z[k]), b = std::min(zHigh, z[k + 1]);
        if (b > a) integral += 0.5 * (at(a, k) + at(b, k)) * (b - a);  // trapezoid: exact on a linear segment
    }
    return integral / (zHigh - zLow);
}

void ThermalField::checkCovers(double zMin, double zMax, const std::string& what) const {
    const double tol = 1e-9;
    if (zMin < axial.front() - tol || zMax > axial.back() + tol)
        throw std::runtime_error(
            fmt::format("thermal-displacement file {}/axial covers z = {:g} … {:g} m, but {} needs {:g} … {:g} m",
                        where, axial.front(), axial.back(), what, zMin, zMax));
}

ThermalDisplacement readThermalDisplacementFile(const std::string& path) {
    const Quiet quiet;
    const Reader r(path);
    const std::string format = r.stringAttribute("format");
    if (format != kThermalFormat)
        r.fail(fmt::format("root attribute 'format' is \"{}\", expected \"{}\"", format, kThermalFormat));
    // `format_version`, as in the reduced-body file; files of earlier builds call it `version`.
    const std::string versionName = r.hasAttribute("format_version") ? "format_version" : "version";
    const long long version = r.integerAttribute(versionName);
    if (version != kThermalFormatVersion)
        r.fail(fmt::format("root attribute '{}' is {}, this build reads version {}", versionName, version,
                           kThermalFormatVersion));
    ThermalDisplacement t;
    t.path = path;
    if (r.has("/piston")) t.piston = r.field("/piston");
    if (r.has("/liner")) t.liner = r.field("/liner");
    if (!t.piston && !t.liner) r.fail("has neither a /piston nor a /liner group");
    if (t.piston && r.has("/piston/ring_belt")) t.pistonRingBelt = r.profile("/piston/ring_belt");
    return t;
}

}  // namespace flexehd::cosim
