#pragma once
// LinerVibrationReport: the slap-noise figures of a run's liner vibration record (acoustics.h5,
// docs/acoustics.md §8–9): over one cycle (720°) of the record, each surface point's normal
// velocity v_n = ẏ (n_iᵀ Φ_i)ᵀ, its spectrum (acoustics::SpectrumAnalyzer), the equivalent
// radiated power per bin, in 1/3-octave bands up to the record's range and per engine order, and
// its band power over the crank angle (frames of a given crank-angle length, half overlapping).
// Writes acoustics.json, acoustics.csv (the bands), acoustics_spectrum.csv (per bin) and
// acoustics_map.csv (crank angle × band) into the results directory.
#include <string>

#include <nlohmann/json.hpp>

#include "acoustics/SpectralWindow.hpp"

namespace flexehd::cosim {

struct LinerVibrationOptions {
    acoustics::WindowKind window = acoustics::WindowKind::Hann;
    double frameDeg = 60.0;  ///< °, the crank-angle map's frame length (hop: half of it)
    int orders = 10;         ///< the strongest engine orders listed
};

/// Reads dir/acoustics.h5 and writes the report's files; returns acoustics.json's content. Throws
/// std::runtime_error naming the file and what is wrong (missing, not a record, too short).
nlohmann::json reportLinerVibration(const std::string& dir, const LinerVibrationOptions& options = {});

}  // namespace flexehd::cosim
