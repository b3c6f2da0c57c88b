#pragma once
// Calibration of convective boundary parameters to measured temperatures (templugs),
// docs/thermal.md §2. Unknowns q: ln s_g for a factor s_g on a group's heat-transfer
// coefficient (positive by construction) and/or T_g for its fluid temperature (K).
// Residuals r_i(q) = T(x_i; q) − T_i^meas at the measurement points, with T(x_i) the
// FE field interpolated by the shape functions of the tetrahedron containing x_i.
// Levenberg–Marquardt (Marquardt's diagonal scaling): (JᵀJ + λ diag JᵀJ) δ = −Jᵀr, the
// Jacobian J = ∂T(x_i)/∂q_j from SteadyHeatConduction::solveWithSensitivity (one
// factorization per parameter set).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/PointLocator.hpp"
#include "fem/SteadyHeatConduction.hpp"

namespace flexehd::fem {

struct CalibrationParameter {
    enum class Kind { HeatTransferScale, FluidTemperature };
    std::string group;  ///< one of the conduction problem's convection boundaries
    Kind kind = Kind::HeatTransferScale;
    std::string label() const;  ///< "h factor on 'crown'", "fluid temperature on 'crown'"
};

struct TemperatureMeasurement {
    std::string name;          ///< for messages and reports
    Eigen::Vector3d position;  ///< m, mesh coordinates
    double temperature = 0.0;  ///< K
};

struct CalibrationOptions {
    double tolerance = 5.0;  ///< K: an RMS residual above this means the data are not matched
    int maxIterations = 100;
    double minScale = 1e-3, maxScale = 1e3;                 ///< bounds of h factors
    double minFluidTemperature = 1.0, maxFluidTemperature = 5000.0;  ///< K
};

struct CalibrationResult {
    ConvectionParameters parameters;  ///< all boundaries, fitted values in place
    Eigen::VectorXd values;           ///< per calibration parameter: factor s_g or T_g (K)
    std::vector<bool> atBound;        ///< per calibration parameter
    Eigen::VectorXd computed;         ///< K, model temperature at each measurement
    Eigen::VectorXd residuals;        ///< K, computed − measured
    Eigen::VectorXd temperature;      ///< K, nodal field for the fitted parameters
    double rms = 0.0, maxAbs = 0.0;   ///< K
    int worst = -1;                   ///< measurement with the largest |residual|
    double initialRms = 0.0;          ///< K, before calibration
    int iterations = 0, evaluations = 0;
    bool converged = false;
    bool matched = false;  ///< converged, rms <= tolerance and no parameter at a bound
    std::string message;   ///< why not matched ("" if matched)
};

class ThermalCalibration {
public:
    /// Locates the measurement points. Throws std::invalid_argument naming the point when
    /// one lies outside the mesh, naming the parameter when its group has no convection
    /// boundary or is listed twice, and when there are fewer distinct measurement
    /// positions than parameters (under-determined).
    ThermalCalibration(const SteadyHeatConduction& problem, std::vector<CalibrationParameter> parameters,
                       std::vector<TemperatureMeasurement> measurements, CalibrationOptions options = {});

    /// Fits the parameters starting from the problem's nominal values. Throws
    /// std::invalid_argument when a parameter does not affect any measured temperature or
    /// the measurements cannot separate parameters (rank-deficient Jacobian).
    CalibrationResult run() const;

    const std::vector<PointLocation>& locations() const { return locations_; }

private:
    // The fit's unknowns q: q_j = ln s_g (heat-transfer scale) or T_g (fluid temperature).
    struct Bounds { Eigen::VectorXd lo, hi; };
    /// The model at q: the temperature field, the residuals at the points, their Jacobian in q.
    struct Evaluation {
        Eigen::VectorXd T, r;
        Eigen::MatrixXd J;
        double cost = 0.0;  ///< ½ ‖r‖²
    };
    ConvectionParameters parametersAt(const Eigen::VectorXd& q) const;
    /// The bounds of q and its start (the nominal values, clamped).
    Bounds bounds(Eigen::VectorXd& q) const;
    Evaluation evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& measured) const;
    /// Throws when a parameter moves no measured temperature or the columns are dependent.
    void requireIdentifiable(const Eigen::MatrixXd& J) const;
    /// Levenberg–Marquardt with bounds from q, cur; returns whether it converged.
    bool fit(Eigen::VectorXd& q, Evaluation& cur, const Bounds& b, const Eigen::VectorXd& measured, int& iterations,
             int& evaluations) const;
    /// The result at the fit's end, with the diagnosis when it does not match the measurements.
    CalibrationResult result(const Eigen::VectorXd& q, const Evaluation& cur, const Bounds& b,
                             const Eigen::VectorXd& measured) const;

    const SteadyHeatConduction& problem_;
    std::vector<CalibrationParameter> parameters_;
    std::vector<TemperatureMeasurement> measurements_;
    CalibrationOptions options_;
    std::vector<PointLocation> locations_;
    std::vector<int> boundary_;  ///< per parameter: index of its convection boundary
};

}  // namespace flexehd::fem
