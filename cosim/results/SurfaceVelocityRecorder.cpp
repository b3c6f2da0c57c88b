#include "cosim/results/SurfaceVelocityRecorder.hpp"

#include <cmath>
#include <utility>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "fem/AtomicFile.hpp"
#include "fem/BoundarySurface.hpp"
#include "modal/Hdf5Writer.hpp"
#include "modal/ModalSuperposition.hpp"

namespace flexehd::cosim {

SurfaceVelocityRecorder::SurfaceVelocityRecorder(const EngineCase& c, const modal::ReducedBody& liner,
                                                 const std::vector<int>& held, int modeOffset, std::string path)
    : spec_(c.acoustics),
      rpm_(c.engine.speedRpm),
      maxStepDeg_(c.time.maxStepDeg),
      offset_(modeOffset),
      modes_(liner.numModes()),
      path_(std::move(path)),
      rate_(c.acoustics.sampleRateHz()),
      propagator_(liner, held),
      compliance_(modal::ModalSuperposition(liner).compliance(held)),
      mass_(liner.massMatrix),
      stiffness_(liner.stiffnessMatrix) {
    if (!liner.mesh.hasGroup(spec_.surface) || liner.mesh.group(spec_.surface).dim != 2)
        throw std::invalid_argument(fmt::format("acoustics.surface: the liner's mesh ({}) has no surface group '{}' "
                                                "(its groups: {})",
                                                liner.meshPath, spec_.surface, liner.mesh.groupNames()));
    // Above the highest fixed-interface normal mode the basis misses modes: the record would show
    // a response the body cannot have (docs/acoustics.md §8).
    if (const double covered = modal::normalModesUpToHz(liner); spec_.upToHz > covered)
        throw std::invalid_argument(fmt::format(
            "acoustics.up_to_hz: {:g} Hz is above the liner's normal modes: its reduced body {} keeps the "
            "fixed-interface normal modes up to {:.6g} Hz ({}). Reduce the liner again with `flexehd reduce "
            "--cutoff {:g}` (every normal mode below that frequency), or set up_to_hz to at most {:.6g} Hz",
            spec_.upToHz, c.linerBody.file.empty() ? liner.meshPath : c.linerBody.file, covered,
            liner.settings.cutoffHz > 0.0 ? fmt::format("reduced with --cutoff {:g}", liner.settings.cutoffHz)
                                          : fmt::format("reduced with --modes {}", liner.settings.normalModes),
            spec_.upToHz, covered));
    surfaceShapes(liner);
}

void SurfaceVelocityRecorder::surfaceShapes(const modal::ReducedBody& liner) {
    // Each node's area vector a_i: a third of the outward area vector of each flat sub-triangle it
    // is a vertex of (a quadratic triangle split at its mid-side nodes into four), so that every
    // node has a positive share and a normal of its own neighbourhood.
    const fem::Mesh& mesh = liner.mesh;
    const fem::BoundarySurface surface(mesh, spec_.surface);
    const bool quadratic = mesh.surface.nodes.rows() == 6;
    static const int kLinear[1][3] = {{0, 1, 2}};
    static const int kQuadratic[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
    Eigen::Matrix3Xd a = Eigen::Matrix3Xd::Zero(3, mesh.numNodes());
    for (std::size_t k = 0; k < surface.triangles().size(); ++k) {
        const fem::Index t = surface.triangles()[k];
        const double sign = surface.orientation()[k];
        for (int sub = 0; sub < (quadratic ? 4 : 1); ++sub) {
            const int* v = quadratic ? kQuadratic[sub] : kLinear[sub];
            const fem::Index n0 = mesh.surface.nodes(v[0], t), n1 = mesh.surface.nodes(v[1], t),
                             n2 = mesh.surface.nodes(v[2], t);
            const Eigen::Vector3d e1 = mesh.nodes.col(n1) - mesh.nodes.col(n0), e2 = mesh.nodes.col(n2) - mesh.nodes.col(n0);
            const Eigen::Vector3d third = sign / 6.0 * e1.cross(e2);
            for (fem::Index n : {n0, n1, n2}) a.col(n) += third;
        }
    }
    const std::vector<fem::Index> nodes = mesh.groupNodes(spec_.surface);
    const auto p = static_cast<Eigen::Index>(nodes.size());
    // The flat sub-triangles by point index, outward (the ParaView surface of the band levels).
    std::vector<int> point(static_cast<std::size_t>(mesh.numNodes()), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i) point[static_cast<std::size_t>(nodes[i])] = static_cast<int>(i);
    triangles_.clear();
    for (std::size_t k = 0; k < surface.triangles().size(); ++k) {
        const fem::Index t = surface.triangles()[k];
        for (int sub = 0; sub < (quadratic ? 4 : 1); ++sub) {
            const int* v = quadratic ? kQuadratic[sub] : kLinear[sub];
            int corner[3];
            for (int c = 0; c < 3; ++c) corner[c] = point[static_cast<std::size_t>(mesh.surface.nodes(v[c], t))];
            if (surface.orientation()[k] < 0) std::swap(corner[1], corner[2]);
            triangles_.insert(triangles_.end(), corner, corner + 3);
        }
    }
    normalShapes_.resize(p, modes_);
    areas_.resize(p);
    points_.resize(3, p);
    normals_.resize(3, p);
    for (Eigen::Index i = 0; i < p; ++i) {
        const fem::Index n = nodes[static_cast<std::size_t>(i)];
        areas_[i] = a.col(n).norm();
        normals_.col(i) = a.col(n) / areas_[i];
        points_.col(i) = mesh.nodes.col(n);
        normalShapes_.row(i) = normals_.col(i).transpose() * liner.shapes.middleRows(3 * n, 3);
    }
}

void SurfaceVelocityRecorder::stepAccepted(const AcceptedStep& step) {
    const StepState& s = step.state;
    const Eigen::VectorXd force = modalForce(s);
    if (!force.allFinite())
        throw std::runtime_error(fmt::format("acoustics: the modal force on the liner is not finite at {:.4f} deg",
                                             crankAngle720(s.crankDeg)));
    if (!started_) {  // the liner's forced response starts at rest, in equilibrium with the first force
        y_ = compliance_ * force;
        w_ = Eigen::VectorXd::Zero(modes_);
        force_ = force;
        lastTime_ = s.time;
        lastAngle_ = s.crankDeg;
    }
    if (!started_ || step.cycle != cycle_) {
        // A cycle's grid starts at the state it starts from: the last one of the cycle before
        // (the run's first accepted step for the first cycle).
        started_ = true;
        cycle_ = step.cycle;
        origin_ = lastTime_;
        times_.assign(1, origin_);
        angles_.assign(1, crankAngle720(lastAngle_));
        velocities_.assign(1, w_);
        work_ = workScale_ = 0.0;
        steps_ = 0;
        damped_ = {};
        storedAtStart_ = storedEnergy();
    }
    const double span = s.time - lastTime_;
    if (span < 0.0)
        throw std::logic_error(fmt::format("acoustics: an accepted step goes back in time, {:.9g} s after {:.9g} s",
                                           s.time, lastTime_));
    if (span == 0.0) {  // the first state again: its force is the one to start from
        force_ = force;
        return;
    }
    // The grid's samples in (t_n−1, t_n], and the step's end: the exact response to the force
    // linear between the two states.
    std::vector<double> taus;
    for (auto k = static_cast<long long>(times_.size());; ++k) {
        const double t = origin_ + static_cast<double>(k) / rate_;
        if (t > s.time) break;
        times_.push_back(t);
        angles_.push_back(crankAngle720(lastAngle_ + (t - lastTime_) / span * (s.crankDeg - lastAngle_)));
        taus.push_back(t - lastTime_);
    }
    taus.push_back(span);
    Eigen::MatrixXd q, v;
    propagator_.responseWithin(y_, w_, force_, force, span, taus, q, v);
    for (Eigen::Index j = 0; j + 1 < v.cols(); ++j) velocities_.push_back(v.col(j));
    work_ += propagator_.workOver(y_, w_, force_, force, span, q.col(q.cols() - 1));
    workScale_ += std::abs(force.dot(q.col(q.cols() - 1))) + std::abs(force_.dot(y_));
    ++steps_;
    if (quadrature_) {
        const modal::DampedEnergy d = quadrature_->overStep(propagator_, y_, w_, force_, force, span);
        damped_.energy += d.energy;
        damped_.error += d.error;
    }
    y_ = q.col(q.cols() - 1);
    w_ = v.col(v.cols() - 1);
    force_ = force;
    lastTime_ = s.time;
    lastAngle_ = s.crankDeg;
}

double SurfaceVelocityRecorder::storedEnergy() const {
    return 0.5 * w_.dot(mass_ * w_) + 0.5 * y_.dot(stiffness_ * y_);
}

Eigen::VectorXd SurfaceVelocityRecorder::modalForce(const StepState& s) const {
    if (s.f.size() < offset_ + modes_) return Eigen::VectorXd::Zero(modes_);  // the run's start: none yet
    return s.f.segment(offset_, modes_);
}

Eigen::MatrixXd SurfaceVelocityRecorder::sampleVelocities() const {
    Eigen::MatrixXd v(static_cast<Eigen::Index>(velocities_.size()), modes_);
    for (std::size_t k = 0; k < velocities_.size(); ++k) v.row(static_cast<Eigen::Index>(k)) = velocities_[k].transpose();
    return v;
}

void SurfaceVelocityRecorder::cycleEnded(const CycleEnd& end) {
    if (times_.size() < 2) return;
    write(end.cycle, end.last);
    ++written_;
}

void SurfaceVelocityRecorder::write(int cycle, bool last) const {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const RowMajor velocity = sampleVelocities();
    const RowMajor shapes = normalShapes_;
    const RowMajor points = points_.transpose(), normals = normals_.transpose();
    const auto n = static_cast<unsigned long long>(times_.size()), m = static_cast<unsigned long long>(modes_),
               p = static_cast<unsigned long long>(areas_.size());
    fem::writeAtomically(path_, [&](const std::string& tmp) {
        modal::Hdf5Writer w(tmp, "acoustics record", path_);
        w.stringAttribute("/", "format", "flexehd-acoustics");
        w.intAttribute("/", "format_version", 3);
        w.stringAttribute("/", "surface", spec_.surface);
        w.doubleAttribute("/", "up_to_hz", spec_.upToHz);
        w.doubleAttribute("/", "sample_rate_hz", rate_);
        w.doubleAttribute("/", "speed_rpm", rpm_);
        w.doubleAttribute("/", "max_step_deg", maxStepDeg_);
        w.intAttribute("/", "cycle", cycle);
        w.intAttribute("/", "last_cycle", last ? 1 : 0);
        w.doubleAttribute("/", "cycle_time_s", lastTime_ - origin_);
        w.doubleAttribute("/", "liner_work_in_j", work_);
        w.doubleAttribute("/", "liner_stored_change_j", storedEnergy() - storedAtStart_);
        w.doubles("/time_s", {n}, times_.data());
        w.doubles("/crank_deg", {n}, angles_.data());
        w.group("/liner");
        w.doubles("/liner/modal_velocity", {n, m}, velocity.data());
        w.group("/surface");
        w.doubles("/surface/points_m", {p, 3}, points.data());
        w.doubles("/surface/normals", {p, 3}, normals.data());
        w.doubles("/surface/area_m2", {p}, areas_.data());
        w.doubles("/surface/normal_shapes", {p, m}, shapes.data());
        w.ints("/surface/triangles", {triangles_.size() / 3, 3}, triangles_.data());
        for (const auto& [name, unit] : {std::pair{"/time_s", "s"}, {"/crank_deg", "deg"},
                                         {"/liner/modal_velocity", "1/s (modal)"}, {"/surface/points_m", "m"},
                                         {"/surface/normals", "1"}, {"/surface/area_m2", "m2"},
                                         {"/surface/triangles", "point index"},
                                         {"/surface/normal_shapes", "m/s per unit modal velocity"}})
            w.stringAttribute(name, "units", unit);
        w.close();
    });
}

}  // namespace flexehd::cosim
