#pragma once
// SurfaceVelocityRecorder: the flexible liner's vibration for slap noise (docs/acoustics.md §8,
// case key `acoustics`). Each point of the radiating surface (a node of the liner's surface group
// with its share of the area) moves with the normal velocity
//
//   v_n,i(t) = n_iᵀ Φ_i ẏ(t),
//
// n_i its outward normal and A_i its area from its area vector a_i: a third of the outward area
// vector of each flat sub-triangle it is a vertex of (quadratic triangles split at their mid-side
// nodes into four; a positive share for every node), Φ_i its rows of the liner's mode shapes.
// ẏ is the liner's forced response to the run's modal force on it (the film and contact loads,
// linear in time between the accepted steps), computed exactly by the liner's ModalPropagator:
// every mode rings with its own frequency and damping, whatever the run's step and whatever its
// own response of the liner (dynamic or quasi-static) that the film sees. The recorder samples ẏ
// on a fixed grid of the case's sampling rate over each cycle and writes the cycle's record at
// its end to acoustics.h5, so the file holds the last complete cycle.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cosim/case/EngineCase.hpp"
#include "cosim/coupling/RunObserver.hpp"
#include "modal/DampedEnergyQuadrature.hpp"
#include "modal/ModalPropagator.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class SurfaceVelocityRecorder final : public RunObserver {
public:
    /// liner: the liner's reduced body and its held interfaces; modeOffset: where its modal
    /// coordinates start in the run's modal force (after the piston's); path: the file written at
    /// each cycle's end. Throws std::invalid_argument naming acoustics.surface when the liner's
    /// mesh has no such surface, std::runtime_error when the held liner can move rigidly.
    SurfaceVelocityRecorder(const EngineCase& c, const modal::ReducedBody& liner, const std::vector<int>& held,
                            int modeOffset, std::string path);

    void stepAccepted(const AcceptedStep& step) override;
    void cycleEnded(const CycleEnd& end) override;

    /// Normal velocity per unit modal velocity of each surface point (m/s per unit ẏ), points × modes.
    const Eigen::MatrixXd& normalShapes() const { return normalShapes_; }
    const Eigen::VectorXd& areas() const { return areas_; }     ///< m², per point
    const Eigen::Matrix3Xd& points() const { return points_; }  ///< m, liner frame
    const Eigen::Matrix3Xd& normals() const { return normals_; }
    double sampleRate() const { return rate_; }  ///< Hz
    /// The current cycle's samples: times (s), crank angles (°, 0–720), modal velocities (samples × modes).
    const std::vector<double>& sampleTimes() const { return times_; }
    const std::vector<double>& sampleAngles() const { return angles_; }
    Eigen::MatrixXd sampleVelocities() const;
    /// Over the current cycle's steps: the work the run's force did on the liner, ∫ fᵀq̇ dt (J,
    /// exact for the force linear between steps), and the change of its stored energy
    /// ½ q̇ᵀ M q̇ + ½ qᵀ K q (J); their difference is what its modal damping took.
    double cycleWork() const { return work_; }
    double cycleStoredChange() const { return storedEnergy() - storedAtStart_; }
    /// From the next step on, also integrates the energy the liner's modal damping takes,
    /// ∫ q̇ᵀ C q̇ dt, by Gauss–Legendre quadrature of `points` and twice as many points on each step
    /// (modal::DampedEnergyQuadrature): a check of the balance W = ΔE + D that does not go
    /// through W − ΔE. Off by default (it costs 3 × points response evaluations per step).
    void integrateDampedEnergy(int points) { quadrature_.emplace(points); }
    /// Over the current cycle's steps (with integrateDampedEnergy): the damped energy (J, the
    /// finer rule's) and its quadrature error bound Σ |D_2m − D_m| over the steps (J).
    double cycleDampedQuadrature() const { return damped_.energy; }
    double cycleDampedQuadratureError() const { return damped_.error; }
    /// Σ (|f₊ᵀq₊| + |fₙᵀqₙ|) over the current cycle's steps (J): the terms the exact work is the
    /// differences of, whose size sets its round-off.
    double cycleWorkScale() const { return workScale_; }
    /// The number of steps in the current cycle.
    int cycleSteps() const { return steps_; }
    int cyclesWritten() const { return written_; }

private:
    void surfaceShapes(const modal::ReducedBody& liner);
    void write(int cycle, bool last) const;
    Eigen::VectorXd modalForce(const StepState& s) const;  // the liner's part of s.f (zero before any)
    double storedEnergy() const;  // ½ ẏᵀ M ẏ + ½ yᵀ K y of the response's state

    AcousticsSpec spec_;
    double rpm_, maxStepDeg_;
    int offset_, modes_;
    std::string path_;
    double rate_;
    Eigen::MatrixXd normalShapes_;
    Eigen::VectorXd areas_;
    Eigen::Matrix3Xd points_, normals_;
    std::vector<int> triangles_;  // 3 point indices per flat sub-triangle, outward
    // The sampling: the grid's origin (s) and the last accepted state (none before the first step).
    int cycle_ = 0;
    double origin_ = 0.0, lastTime_ = 0.0, lastAngle_ = 0.0;
    bool started_ = false;
    modal::ModalPropagator propagator_;
    Eigen::MatrixXd compliance_;     // quasi-static: the response's start
    Eigen::MatrixXd mass_, stiffness_;  // M_r, K_r
    double work_ = 0.0, storedAtStart_ = 0.0;  // J, over the current cycle
    double workScale_ = 0.0;                   // J, Σ |f₊ᵀq₊| + |fₙᵀqₙ| over the current cycle
    int steps_ = 0;                            // the current cycle's
    std::optional<modal::DampedEnergyQuadrature> quadrature_;
    modal::DampedEnergy damped_;               // J, over the current cycle (with quadrature_)
    Eigen::VectorXd y_, w_, force_;  // the forced response's state and force at the last accepted step
    std::vector<double> times_, angles_;
    std::vector<Eigen::VectorXd> velocities_;
    int written_ = 0;
};

}  // namespace flexehd::cosim
