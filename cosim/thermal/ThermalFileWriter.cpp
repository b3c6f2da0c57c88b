#include "cosim/thermal/ThermalFileWriter.hpp"

#include "modal/Hdf5Writer.hpp"

#include <cmath>
#include <stdexcept>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {
namespace {

using Writer = modal::Hdf5Writer;

// GROUP/ring_belt: the surface temperature's profile over z.
void writeRingBelt(Writer& w, const std::string& g, const AxialProfile& p, const std::string& surface) {
    const auto n = static_cast<unsigned long long>(p.axial.size());
    if (n < 2 || p.values.size() != p.axial.size()) w.fail(g + ": inconsistent profile sizes");
    for (std::size_t k = 0; k < p.axial.size(); ++k) {
        if (!std::isfinite(p.axial[k]) || (k > 0 && !(p.axial[k] > p.axial[k - 1])))
            w.fail(g + ": z values are not finite and strictly increasing");
        if (!std::isfinite(p.values[k]) || !(p.values[k] > 0.0))
            w.fail(g + ": a temperature is not finite and positive");
    }
    w.group(g);
    if (!surface.empty()) w.stringAttribute(g, "surface", surface);
    w.stringAttribute(g, "quantity", "circumferential mean temperature of the outer surface");
    w.doubles(g + "/z_m", {n}, p.axial.data());
    w.doubles(g + "/temperature_k", {n}, p.values.data());
    w.stringAttribute(g + "/z_m", "units", "m");
    w.stringAttribute(g + "/temperature_k", "units", "K");
}

void writeBody(Writer& w, const std::string& g, const ThermalBodyTable& body) {
    const SurfaceTable& t = body.table;
    const auto nz = static_cast<unsigned long long>(t.axial.size()), nt = static_cast<unsigned long long>(t.theta.size());
    if (nz < 2 || nt < 3 || static_cast<unsigned long long>(t.radial.rows()) != nz || static_cast<unsigned long long>(t.radial.cols()) != nt ||
        t.onSurface.rows() != t.radial.rows() || t.onSurface.cols() != t.radial.cols())
        w.fail(g + ": inconsistent table sizes");
    if (!t.radial.allFinite()) w.fail(g + ": radial displacement has a non-finite value");
    for (std::size_t k = 1; k < t.axial.size(); ++k)
        if (!(t.axial[k] > t.axial[k - 1])) w.fail(g + ": axial values are not strictly increasing");
    w.group(g);
    w.stringAttribute(g, "units", "m");
    for (const auto& [name, value] : body.attributes) {
        if (!std::isfinite(value)) w.fail(g + "@" + name + " is not finite");
        w.doubleAttribute(g, name, value);
    }
    for (const auto& [name, value] : body.textAttributes) w.stringAttribute(g, name, value);
    w.doubles(g + "/axial", {nz}, t.axial.data());
    w.doubles(g + "/theta", {nt}, t.theta.data());
    w.doubles(g + "/radial_displacement", {nz, nt}, t.radial.data());
    w.bytes(g + "/on_surface", {nz, nt}, t.onSurface.data());
    for (const auto& [name, unit] : {std::pair{"axial", "m"}, {"theta", "rad"}, {"radial_displacement", "m"}, {"on_surface", "1"}})
        w.stringAttribute(g + "/" + name, "units", unit);
    if (body.ringBelt) writeRingBelt(w, g + "/ring_belt", *body.ringBelt, body.ringBeltSurface);
}

}  // namespace

void writeThermalFile(const std::string& path, const std::optional<ThermalBodyTable>& piston,
                      const std::optional<ThermalBodyTable>& liner) {
    if (!piston && !liner) throw std::runtime_error("thermal file " + path + ": neither piston nor liner to write");
    fem::writeAtomically(path, [&](const std::string& tmp) {
        Writer w(tmp, "thermal file", path);
        w.stringAttribute("/", "format", "flexehd-thermal");
        w.intAttribute("/", "format_version", 1);
        if (piston) writeBody(w, "/piston", *piston);
        if (liner) writeBody(w, "/liner", *liner);
        w.close();
    });
}

}  // namespace flexehd::cosim
