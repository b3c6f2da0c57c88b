#include "cosim/results/LinerVibrationReport.hpp"

#include <algorithm>
#include <map>
#include <cmath>
#include <stdexcept>

#include <Eigen/Core>
#include <fmt/format.h>

#include "acoustics/EngineOrderSpectrum.hpp"
#include "acoustics/OneThirdOctaveBands.hpp"
#include "acoustics/RadiatedPower.hpp"
#include "acoustics/ShortTimeRadiatedPower.hpp"
#include "acoustics/SoundPowerLevel.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"
#include "cosim/io/JsonText.hpp"
#include "cosim/io/VtuWriter.hpp"
#include "fem/AtomicFile.hpp"
#include "modal/Hdf5Reader.hpp"

namespace flexehd::cosim {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Record {
    double sampleRate = 0.0, upTo = 0.0, rpm = 0.0;
    int cycle = 0;
    bool last = false;
    std::string surface;
    std::vector<double> time, crank;
    Eigen::MatrixXd velocity;  // samples × points, m/s
    Eigen::VectorXd area;      // m²
    bool hasEnergy = false;    // format 2 and later: the work on the liner over the cycle's steps
    double cycleTime = 0.0, work = 0.0, storedChange = 0.0;  // s, J, J
    Eigen::Matrix3Xd points;     // m, the surface's points (format 3)
    std::vector<int> triangles;  // 3 point indices each (format 3)
    bool hasSurface = false;
};

Eigen::MatrixXd matrix(const modal::Hdf5Reader& r, const std::string& name, unsigned long long rows,
                       unsigned long long cols) {
    std::vector<unsigned long long> dims;
    const std::vector<double> v = r.doubles(name, dims);
    if (dims.size() != 2 || dims[0] != rows || dims[1] != cols)
        r.fail(fmt::format("dataset {} is not {} × {}", name, rows, cols));
    return Eigen::Map<const RowMajor>(v.data(), static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
}

// One cycle of the record: the samples before t_0 + 720° (the last sample of a whole cycle repeats
// the first).
Record readRecord(const std::string& path) {
    const modal::Hdf5Reader r(path, "acoustics record");
    if (r.stringAttribute("/", "format") != "flexehd-acoustics") r.fail("not a flexehd acoustics record (format)");
    const int version = r.intAttribute("/", "format_version");
    if (version < 1 || version > 3)
        r.fail(fmt::format("format_version {} is not one this flexehd reads (1 to 3); a newer flexehd wrote it", version));
    Record rec;
    rec.sampleRate = r.doubleAttribute("/", "sample_rate_hz");
    rec.upTo = r.doubleAttribute("/", "up_to_hz");
    rec.rpm = r.doubleAttribute("/", "speed_rpm");
    rec.cycle = r.intAttribute("/", "cycle");
    rec.last = r.intAttribute("/", "last_cycle") != 0;
    rec.surface = r.stringAttribute("/", "surface");
    std::vector<unsigned long long> dims, shapeDims;
    rec.time = r.doubles("/time_s", dims);
    rec.crank = r.doubles("/crank_deg", dims);
    const std::vector<double> shapeValues = r.doubles("/surface/normal_shapes", shapeDims);
    const std::vector<double> area = r.doubles("/surface/area_m2", dims);
    if (shapeDims.size() != 2 || dims.size() != 1 || dims[0] != shapeDims[0])
        r.fail("/surface/area_m2 and /surface/normal_shapes do not have one row per point");
    const unsigned long long samples = rec.time.size(), points = shapeDims[0], modes = shapeDims[1];
    const Eigen::MatrixXd modal = matrix(r, "/liner/modal_velocity", samples, modes);
    const Eigen::Map<const RowMajor> shapes(shapeValues.data(), static_cast<Eigen::Index>(points),
                                            static_cast<Eigen::Index>(modes));
    const double cycleEnd = rec.time.front() + 120.0 / rec.rpm;
    std::size_t n = 0;
    while (n < rec.time.size() && rec.time[n] < cycleEnd - 1e-9 / rec.sampleRate) ++n;
    if (n < 8) r.fail(fmt::format("{} samples in its cycle: too few for a spectrum", n));
    if (version >= 2) {
        rec.hasEnergy = true;
        rec.cycleTime = r.doubleAttribute("/", "cycle_time_s");
        rec.work = r.doubleAttribute("/", "liner_work_in_j");
        rec.storedChange = r.doubleAttribute("/", "liner_stored_change_j");
    }
    if (version >= 3) {
        rec.hasSurface = true;
        rec.points = matrix(r, "/surface/points_m", points, 3).transpose();
        std::vector<unsigned long long> triangleDims;
        const std::vector<double> corners = r.doubles("/surface/triangles", triangleDims);
        if (triangleDims.size() != 2 || triangleDims[1] != 3) r.fail("dataset /surface/triangles is not T × 3");
        for (const double c : corners) {
            if (c < 0.0 || c >= double(points) || c != std::floor(c))
                r.fail(fmt::format("dataset /surface/triangles holds {}, not a point index below {}", c, points));
            rec.triangles.push_back(static_cast<int>(c));
        }
    }
    rec.time.resize(n);
    rec.crank.resize(n);
    rec.velocity = modal.topRows(static_cast<Eigen::Index>(n)) * shapes.transpose();
    rec.area = Eigen::Map<const Eigen::VectorXd>(area.data(), static_cast<Eigen::Index>(area.size()));
    return rec;
}

// The liner's energy over the record's cycle: the work the film and contacts did on it, the
// change of its stored energy, and their difference, the energy its modal damping took.
nlohmann::json energyBalance(const Record& rec) {
    return {{"work_in_j", rec.work},
            {"stored_change_j", rec.storedChange},
            {"damped_j", rec.work - rec.storedChange},
            {"input_power_mean_w", rec.cycleTime > 0.0 ? rec.work / rec.cycleTime : 0.0}};
}

// The surface's normal velocity per 1/3-octave band up to the range: each point's rms (m/s) and
// its level re 1 nm/s (ISO 1683), as a ParaView surface (acoustics_surface.vtu).
void writeBandVelocities(const std::string& path, const Record& rec, const acoustics::VelocitySpectrum& spectrum) {
    const Eigen::MatrixXd meanSquare = spectrum.meanSquare();  // bins × points
    const Eigen::VectorXd& f = spectrum.frequency_hz();
    std::map<int, Eigen::VectorXd> bands;  // band k → per point mean square
    for (Eigen::Index b = 1; b < f.size(); ++b) {
        const int k = acoustics::OneThirdOctaveBand::containing(f[b]);
        if (acoustics::OneThirdOctaveBand::midFrequency_hz(k) > rec.upTo) continue;
        auto [it, fresh] = bands.try_emplace(k, Eigen::VectorXd::Zero(meanSquare.cols()));
        it->second += meanSquare.row(b).transpose();
    }
    std::vector<PointField> fields;
    Eigen::VectorXd total = Eigen::VectorXd::Zero(meanSquare.cols());
    auto add = [&](const std::string& band, const Eigen::VectorXd& ms) {
        const Eigen::RowVectorXd rms = ms.cwiseSqrt().transpose();
        fields.push_back({"normal_velocity_rms_m_per_s_" + band, rms});
        fields.push_back({"normal_velocity_level_db_" + band,
                          rms.unaryExpr([](double v) { return v > 0.0 ? 20.0 * std::log10(v / 1e-9) : -100.0; })});
    };
    for (const auto& [k, ms] : bands) {
        total += ms;
        add(fmt::format("{:.0f}hz", acoustics::OneThirdOctaveBand::midFrequency_hz(k)), ms);
    }
    add("total", total);
    std::rotate(fields.begin(), fields.end() - 2, fields.end());  // the total first: ParaView's active scalar
    writeTriangleSurfaceVtu(path, rec.points, rec.triangles, fields);
}

nlohmann::json level(double power) {
    return power > 0.0 ? nlohmann::json(acoustics::soundPowerLevel_dB(power)) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json reportLinerVibration(const std::string& dir, const LinerVibrationOptions& o) {
    const Record rec = readRecord(dir + "/acoustics.h5");
    const auto n = static_cast<int>(rec.time.size());
    acoustics::SpectrumAnalyzer analyzer(n, rec.sampleRate, o.window);
    const acoustics::VelocitySpectrum spectrum = analyzer.analyze(rec.velocity);
    const acoustics::RadiatedPower radiated(rec.area);
    const Eigen::VectorXd perBin = radiated.perBin_W(spectrum);
    const Eigen::VectorXd& f = spectrum.frequency_hz();
    // The bands within the record's range.
    const acoustics::BandSpectrum all = radiated.inOneThirdOctaveBands_W(spectrum);
    nlohmann::json bands = nlohmann::json::array();
    std::string bandCsv = "band_mid_hz,band_lower_hz,band_upper_hz,erp_w,erp_db\n";
    double total = 0.0;
    for (Eigen::Index k = 0; k < all.size(); ++k) {
        if (all.midFrequency_hz[k] > rec.upTo) continue;
        total += all.value[k];
        bands.push_back({{"mid_hz", all.midFrequency_hz[k]}, {"lower_hz", all.lowerEdge_hz[k]},
                         {"upper_hz", all.upperEdge_hz[k]}, {"erp_w", all.value[k]}, {"erp_db", level(all.value[k])}});
        bandCsv += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{}\n", all.midFrequency_hz[k], all.lowerEdge_hz[k],
                               all.upperEdge_hz[k], all.value[k],
                               all.value[k] > 0.0 ? fmt::format("{:.6g}", acoustics::soundPowerLevel_dB(all.value[k])) : "");
    }
    std::string spectrumCsv = "frequency_hz,order,erp_w\n";
    const acoustics::EngineOrderSpectrum orders(f, perBin, rec.rpm);
    for (Eigen::Index k = 0; k < f.size(); ++k)
        spectrumCsv += fmt::format("{:.9g},{:.9g},{:.9g}\n", f[k], orders.binOrder()[k], perBin[k]);
    nlohmann::json top = nlohmann::json::array();
    for (const acoustics::OrderLine& line : orders.top(o.orders))
        top.push_back({{"order", line.order}, {"frequency_hz", line.frequency_hz}, {"erp_w", line.power},
                       {"erp_db", level(line.power)}});
    // The crank-angle map: frames of frameDeg, half overlapping.
    const double samplesPerDeg = rec.sampleRate / (6.0 * rec.rpm);
    const int frame = std::clamp(static_cast<int>(std::lround(o.frameDeg * samplesPerDeg)), 8, n);
    acoustics::ShortTimeRadiatedPower stft(radiated, rec.sampleRate, frame, std::max(1, frame / 2), o.window);
    const acoustics::CrankAngleBandMap map = stft.map(rec.velocity, rec.rpm, rec.crank.front());
    std::string mapCsv = "crank_deg,band_mid_hz,erp_w\n";
    for (Eigen::Index i = 0; i < map.power_W.rows(); ++i)
        for (Eigen::Index j = 0; j < map.power_W.cols(); ++j)
            if (map.midFrequency_hz[j] <= rec.upTo)
                mapCsv += fmt::format("{:.6g},{:.9g},{:.9g}\n", std::fmod(map.crankAngle_deg[i] + 720.0, 720.0),
                                      map.midFrequency_hz[j], map.power_W(i, j));
    const double meanSquare = (rec.velocity.cwiseAbs2().colwise().mean() * rec.area).value() / rec.area.sum();
    nlohmann::json doc = {
        {"record",
         {{"cycle", rec.cycle}, {"last_cycle", rec.last}, {"surface", rec.surface}, {"points", rec.area.size()},
          {"area_m2", rec.area.sum()}, {"samples", n}, {"sample_rate_hz", rec.sampleRate}, {"up_to_hz", rec.upTo},
          {"bin_hz", spectrum.binWidth_hz()}, {"window", analyzer.window().name()}, {"speed_rpm", rec.rpm}}},
        {"velocity", {{"rms_m_per_s", std::sqrt(meanSquare)}}},
        {"erp", {{"total_w", total}, {"total_db", level(total)}, {"bands", bands}, {"orders", top}}},
        {"map", {{"frame_deg", frame / samplesPerDeg}, {"frames", map.power_W.rows()}}}};
    if (rec.hasEnergy) doc["energy"] = energyBalance(rec);
    if (rec.hasSurface) writeBandVelocities(dir + "/acoustics_surface.vtu", rec, spectrum);
    fem::writeTextAtomically(dir + "/acoustics.json", jsonText(doc, 2) + "\n");
    fem::writeTextAtomically(dir + "/acoustics.csv", bandCsv);
    fem::writeTextAtomically(dir + "/acoustics_spectrum.csv", spectrumCsv);
    fem::writeTextAtomically(dir + "/acoustics_map.csv", mapCsv);
    return doc;
}

}  // namespace flexehd::cosim
