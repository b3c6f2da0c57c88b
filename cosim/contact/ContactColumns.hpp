#pragma once
// ContactColumns: the results a film contact adds to a run's outputs by itself (docs/results-format.md,
// "Columns of further contacts"): columns of history.csv after the master's, each with the cycle
// figures summary.json reports of it. The writers take the columns from the contacts; a new
// contact's results need no edit of the master or of a writer.

#include <string>
#include <vector>

namespace flexehd::cosim {

/// How a cycle figure is formed from a column over the last cycle's records: its least or largest
/// value, its time mean (trapezoidal over the steps, as the skirt's mean friction power), or — of
/// a friction power column — its energy over the cycle per swept volume, the contact's friction
/// mean effective pressure (summed with the skirt's into summary.json's `fmep_total_pa`); of a
/// column that is 0 at rest (a ring's position above its lower flank): how often it departs
/// from 0 over the cycle (Departures) and the crank angles (°, 0–720) of the records where it
/// has (DepartureAngles, a list).
enum class CycleStatistic { Minimum, Maximum, Mean, Fmep, Departures, DepartureAngles };

/// One figure of summary.json: its key (dotted for nested objects, with its unit, e.g.
/// "band.friction_power_mean_w") and how it is formed.
struct ColumnFigure {
    std::string key;
    CycleStatistic statistic = CycleStatistic::Mean;
};

/// One column of history.csv: its name (with its unit, e.g. "band_friction_power_w") and the
/// summary figures of it.
struct ContactColumn {
    std::string name;
    std::vector<ColumnFigure> figures;
};

}  // namespace flexehd::cosim
