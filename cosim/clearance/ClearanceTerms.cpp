#include "cosim/clearance/ClearanceTerms.hpp"

#include "cosim/clearance/BoreDistortion.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace flexehd::cosim {

ClearanceTerms::ClearanceTerms(const EngineCase& c, const lube::FilmGrid& grid, double offsetMin, double offsetMax)
    : grid_(&grid), piston_(Eigen::VectorXd::Zero(grid.size())) {
    const double zLo = grid.z(0), zHi = grid.z(grid.nAxial() - 1);
    const double sweepLo = offsetMin + zLo, sweepHi = offsetMax + zHi;  // liner-frame z the grid visits
    const BoreDistortionSpec& d = c.liner.boreDistortion;
    const std::string source = d.file.empty() ? std::string("liner.bore_distortion (inline table)") : d.file;
    if (d.format == BoreDistortionFormat::Fourier)
        distortion_ = fourierDistortionTable(d.fourier, grid, "bore distortion " + source);
    else if (d.format == BoreDistortionFormat::Nodal)
        distortion_ = nodalDistortionTable(d.nodes, grid, sweepLo, sweepHi, "bore distortion " + source);

    if (c.thermal.file.empty()) return;
    const ThermalDisplacement t = readThermalDisplacementFile(c.thermal.file);
    if (t.piston) {
        // Piston mesh frame = film grid frame: z and θ as they are.
        t.piston->checkCovers(zLo, zHi, "the skirt film grid (piston.skirt_bottom … skirt_top)");
        for (int k = 0; k < grid.size(); ++k)
            if (grid.kind(k) != lube::NodeKind::Void)
                piston_[k] = -t.piston->at(grid.z(grid.axialIndex(k)), grid.theta(grid.thetaIndex(k)));
        hasPiston_ = true;
    }
    if (t.liner) {
        t.liner->checkCovers(sweepLo, sweepHi, "the skirt's sweep over the liner between TDC and BDC");
        // The file's rows, interpolated in θ onto the grid's columns: linear in z between them
        // (LinerFieldTable) makes the whole bilinear.
        const std::size_t rows = t.liner->axial.size();
        Eigen::MatrixXd values(Eigen::Index(rows), grid.nTheta());
        for (std::size_t k = 0; k < rows; ++k)
            for (int j = 0; j < grid.nTheta(); ++j)
                values(Eigen::Index(k), j) = t.liner->at(t.liner->axial[k], grid.theta(j));
        linerThermal_ =
            LinerFieldTable(t.liner->axial, std::move(values), "liner thermal displacement " + t.liner->where);
    }
}

void ClearanceTerms::add(double offset, Eigen::VectorXd& h) const {
    if (hasPiston_) h += piston_;
    if (distortion_) distortion_->add(*grid_, offset, 1.0, h);
    if (linerThermal_) linerThermal_->add(*grid_, offset, 1.0, h);
}

std::string ClearanceTerms::summary() const {
    std::string out;
    const auto range = [](const Eigen::MatrixXd& v) {
        return fmt::format("{:.2f} … {:.2f} um", v.minCoeff() * 1e6, v.maxCoeff() * 1e6);
    };
    if (distortion_) out += "bore distortion " + range(distortion_->values());
    if (hasPiston_) {
        double lo = 0.0, hi = 0.0;
        bool first = true;
        for (int k = 0; k < grid_->size(); ++k)
            if (grid_->kind(k) != lube::NodeKind::Void) {
                lo = first ? -piston_[k] : std::min(lo, -piston_[k]);
                hi = first ? -piston_[k] : std::max(hi, -piston_[k]);
                first = false;
            }
        out += (out.empty() ? "" : "; ") + fmt::format("piston thermal u_r {:.2f} … {:.2f} um", lo * 1e6, hi * 1e6);
    }
    if (linerThermal_)
        out += (out.empty() ? "" : "; ") + std::string("liner thermal u_r ") + range(linerThermal_->values());
    return out.empty() ? "no thermal or distortion terms" : out;
}

}  // namespace flexehd::cosim
