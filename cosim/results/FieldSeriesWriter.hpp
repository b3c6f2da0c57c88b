#pragma once
// FieldSeriesWriter: the VTK time series of a run for ParaView (docs/results-format.md).
//
// Each write() adds one snapshot: DIR/vtk/film_NNNNNN.vts (the film grid as a structured grid,
// closed at the periodic seam) and, when given, DIR/vtk/piston_NNNNNN.vtu and
// DIR/vtk/liner_NNNNNN.vtu (the body meshes with displacement vectors for Warp By Vector) and
// DIR/vtk/liner_oil_NNNNNN.vts (the liner's oil layer), written at once: nothing is held in
// memory. commit() makes the snapshots written since the last commit the series — it rewrites
// DIR/film.pvd, DIR/piston.pvd, DIR/liner.pvd and DIR/liner_oil.pvd to list them and then
// deletes the files of the series they replace; discard() deletes them instead. flexehd run
// commits every cycle, so the collections always list the last complete cycle. Every file is
// written atomically (NAME.tmp, then renamed) and a collection lists only files that exist, so a
// run killed at any moment leaves a valid series.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cosim/io/PvdWriter.hpp"
#include "fem/Mesh.hpp"
#include "lube/FilmGrid.hpp"

namespace flexehd::cosim {

/// One snapshot of the film on its grid. Node values in grid order (θ fastest).
struct FilmField {
    const lube::FilmGrid* grid = nullptr;  ///< film frame: node (R cos θ, R sin θ, z)
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< cylinder-frame position of the film frame's origin (m)
    Eigen::VectorXd pressure;         ///< Pa (required)
    Eigen::VectorXd filmThickness;    ///< m (required)
    Eigen::VectorXd contactPressure;  ///< Pa, asperity contact (empty: not written)
    Eigen::VectorXd shearStress;      ///< Pa, axial wall shear on the piston (empty: not written)
    Eigen::VectorXd cavitation;       ///< cavitated fraction 1 − φ, 0 = full film (empty: not written)
    Eigen::VectorXd filmFraction;     ///< film fraction φ of a mass-conserving film (empty: not written)
};

/// One snapshot of a body mesh.
struct BodyField {
    const fem::Mesh* mesh = nullptr;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< cylinder-frame position of the mesh frame's origin (m)
    Eigen::VectorXd displacement;  ///< 3·nodes, m: rigid secondary motion + elastic (`displacement_m`, for Warp By Vector)
    Eigen::VectorXd elastic;       ///< 3·nodes, m: elastic part only (`elastic_displacement_m`; empty: not written)
};

/// One snapshot of the liner's oil layer (LinerOilLayer) on its cells and the film grid's columns.
struct LinerOilField {
    const lube::FilmGrid* grid = nullptr;  ///< its θ columns and radius
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< cylinder-frame position of the liner frame's origin (m)
    const std::vector<double>* z = nullptr;  ///< liner-frame z of the cells' centres (m)
    Eigen::VectorXd thickness;  ///< m, cell-major (c × nθ + j): `oil_thickness_m`
};

/// When a snapshot was taken: the collection's time axis and the crank angle and cycle it
/// stands for, written as field data of each file (docs/results-format.md, "VTK series").
struct SnapshotTime {
    double time = 0.0;      ///< the .pvd time (flexehd run: the crank angle of the written cycle, °)
    double crankDeg = 0.0;  ///< °, the crank angle 0–720 of history.csv
    int cycle = 0;          ///< 1-based cycle number of history.csv
};

class FieldSeriesWriter {
public:
    /// Creates `directory`/vtk. Snapshot files are numbered from 000000.
    explicit FieldSeriesWriter(std::string directory);

    /// Writes one snapshot at `at.time`, which must be finite and larger than the previous one;
    /// each file carries `TimeValue`, `crank_deg` and `cycle` as field data.
    /// Throws std::runtime_error naming the field (and the node) on a size mismatch or a NaN/Inf
    /// value, before any file is written; or naming the file on an I/O error.
    void write(const SnapshotTime& at, const FilmField& film, const BodyField* piston, const BodyField* liner,
               const LinerOilField* oil = nullptr);
    /// The snapshots written since the last commit (or discard) become the series. The first
    /// commit also removes what an earlier run left in the directory: its series files (vtk/film_,
    /// piston_, liner_, liner_oil_ NNNNNN) that this series does not name, and its .pvd files where
    /// this run writes none.
    void commit();
    /// Deletes the snapshots written since the last commit; the series stays as it was.
    void discard();

    /// Number of snapshots written so far (file numbers run on over commits).
    int count() const { return count_; }
    /// Snapshots in the committed series.
    int committed() const { return committedCount_; }

private:
    struct Staged {
        double time;
        std::string film, piston, liner, oil;  ///< relative paths; empty: no such body or layer
    };
    std::string directory_;
    int count_ = 0, committedCount_ = 0;
    std::vector<Staged> staged_;
    std::vector<std::string> committedFiles_;  ///< relative paths of the committed series
    bool earlierRunRemoved_ = false;           ///< the first commit removed an earlier run's series
    void removeEarlierRun(const std::vector<std::string>& files) const;
};

}  // namespace flexehd::cosim
