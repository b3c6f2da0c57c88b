#pragma once
// FilmGrid: the structured lubrication grid on an unwrapped cylinder of radius R.
//
// Nodes sit at (z_i, θ_j): z strictly increasing along the cylinder axis (non-uniform spacing
// allowed), θ uniform. The circumferential direction is either periodic (a full 360°
// circumference, nθ nodes at θ_j = θ0 + 2πj/nθ) or an open arc [θ0, θ1] with nodes on both ends.
// Node-centred finite volumes: each node owns the control volume bounded by the mid-lines to its
// neighbours (half volumes on open edges). Position of a node in the film frame:
// (R cos θ, R sin θ, z). See docs/lube.md §1.
//
// Each node is of one kind:
//  - Film:  pressure unknown (Reynolds equation, possibly cavitated);
//  - Fixed: bearing surface present, pressure prescribed (open edge, supply groove or hole);
//  - Void:  no bearing surface (mask, e.g. skirt relief): pressure = ambient, excluded from the
//           shear, contact and area integrals.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace flexehd::lube {

/// The four edges of the unwrapped grid (the θ edges exist only on an open arc).
enum class Edge { AxialLow, AxialHigh, ArcStart, ArcEnd };

/// Condition on an edge: ambient/supply pressure (Dirichlet) or zero flux (symmetry plane,
/// or an infinitely long bearing when both axial edges are Symmetry).
enum class EdgeCondition { Pressure, Symmetry };

enum class NodeKind : unsigned char { Film, Fixed, Void };

class FilmGrid {
public:
    /// Full 360° circumference (periodic in θ), nθ ≥ 3 nodes, θ_j = θ0 + 2πj/nθ.
    static FilmGrid fullCircumference(double radius, std::vector<double> axial, int nTheta,
                                      double theta0 = 0.0);
    /// Open arc [θ0, θ1] with nθ ≥ 3 nodes including both ends.
    static FilmGrid arc(double radius, std::vector<double> axial, double theta0, double theta1,
                        int nTheta);
    /// n equally spaced values from a to b inclusive (n ≥ 2).
    static std::vector<double> uniform(double a, double b, int n);

    int nAxial() const { return static_cast<int>(z_.size()); }
    int nTheta() const { return nTheta_; }
    int size() const { return nAxial() * nTheta_; }
    /// Node index: θ runs fastest.
    int index(int i, int j) const { return i * nTheta_ + j; }
    int axialIndex(int k) const { return k / nTheta_; }
    int thetaIndex(int k) const { return k % nTheta_; }

    double radius() const { return radius_; }
    bool periodic() const { return periodic_; }
    double z(int i) const { return z_[static_cast<std::size_t>(i)]; }
    const std::vector<double>& axial() const { return z_; }
    double theta(int j) const { return theta0_ + j * dTheta_; }
    /// cos θ_j and sin θ_j, computed once with the grid (the film integrals' frame per node).
    double cosTheta(int j) const { return cosTheta_[static_cast<std::size_t>(j)]; }
    double sinTheta(int j) const { return sinTheta_[static_cast<std::size_t>(j)]; }
    double dTheta() const { return dTheta_; }
    /// Length of the bearing along z and its angular extent.
    double length() const { return z_.back() - z_.front(); }
    double angularExtent() const { return periodic_ ? 2.0 * kPi : (nTheta_ - 1) * dTheta_; }

    /// Control-volume extent of node row i along z (m) and of node column j in θ (rad); a column
    /// cut by an arc end (restrictToArcs) ends halfway to it.
    double axialWidth(int i) const;
    double angularWidth(int j) const { return cvWidth_[static_cast<std::size_t>(j)]; }
    /// The part of the bearing surface column j stands for (rad): its control volume plus, next
    /// to an arc end, the strip from there to the end (where the pressure falls to ambient).
    double coveredAngularWidth(int j) const { return coveredWidth_[static_cast<std::size_t>(j)]; }
    /// The part of coveredAngularWidth(j) on the −θ side of column j (the rest is on the +θ side):
    /// Δθ/2 towards a neighbour on the surface, the distance to the arc end towards one outside.
    double coveredWidthBelow(int j) const { return coveredBelow_[static_cast<std::size_t>(j)]; }
    /// Angular distance across the face between columns j and j + 1 (wrapped): Δθ, or from a
    /// column to the arc end it borders when the other column is outside the arcs.
    double faceAngle(int j) const { return faceAngle_[static_cast<std::size_t>(j)]; }
    /// Control-volume area of node k (m²): the weight of the pressure and of the mass balance.
    double area(int k) const { return radius_ * angularWidth(thetaIndex(k)) * axialWidth(axialIndex(k)); }
    /// Surface area node k stands for (m²): the weight of contact, shear and other fields that
    /// do not vanish at an arc end (= area(k) away from arc ends).
    double surfaceArea(int k) const {
        return radius_ * coveredAngularWidth(thetaIndex(k)) * axialWidth(axialIndex(k));
    }

    /// The bearing surface covers only these arcs of θ (rad, each [lo, hi] with lo < hi, shorter
    /// than a turn on a full circumference and inside [θ0, θ1] on an open arc; pairwise apart by
    /// more than Δθ): nodes outside them become Void, and the columns next to an arc's end are
    /// cut there — their control volume ends halfway to it, their covered width reaches it and
    /// the face towards the Void column spans the distance to it, so that the ambient pressure
    /// sits at the arc's true end (docs/lube.md §1). A column within 1e-6 Δθ of an end becomes
    /// Fixed at ambient. Replaces the arcs of an earlier call; coarsened() keeps them.
    void restrictToArcs(std::vector<std::pair<double, double>> arcs);
    const std::vector<std::pair<double, double>>& arcs() const { return arcs_; }

    /// Edge conditions. Default: Pressure edges at pressure 0 (gauge ambient).
    void setEdge(Edge edge, EdgeCondition condition, double pressure = 0.0);
    EdgeCondition edgeCondition(Edge edge) const { return edges_[static_cast<int>(edge)].condition; }

    /// Ambient pressure (Pa): the pressure on Void nodes and the datum for force integrals.
    void setAmbientPressure(double p);
    double ambientPressure() const { return ambient_; }

    /// Prescribes the pressure of node k (supply groove or hole, pin of a pressure datum).
    void fixNode(int k, double pressure);
    /// Removes node k from the bearing surface (mask): p = ambient, no film there.
    void voidNode(int k);

    NodeKind kind(int k) const { return kind_[static_cast<std::size_t>(k)]; }
    /// All node kinds and prescribed pressures, indexed by node (for assembly loops).
    const NodeKind* kinds() const { return kind_.data(); }
    const double* prescribedPressures() const { return fixedPressure_.data(); }
    /// Prescribed pressure of a Fixed node, ambient for Void, unused for Film.
    double prescribedPressure(int k) const;
    int filmNodeCount() const;

    /// Every other node in each direction (nodes of the coarse grid are nodes of this one,
    /// node kinds and prescribed pressures injected), for grid sequencing. axialMap receives the
    /// fine row of each coarse row: even rows, plus the last row when nAxial is even. Empty when
    /// the θ direction cannot be halved (periodic nTheta odd, open nTheta even) or the coarse
    /// grid would have fewer than 3 rows or 8 columns.
    std::optional<FilmGrid> coarsened(std::vector<int>& axialMap) const;

private:
    static constexpr double kPi = 3.14159265358979323846;
    FilmGrid(double radius, std::vector<double> axial, int nTheta, bool periodic, double theta0,
             double dTheta);
    void refreshKinds();
    void resetColumnGeometry();

    struct EdgeSpec {
        EdgeCondition condition = EdgeCondition::Pressure;
        double pressure = 0.0;
    };
    double radius_;
    std::vector<double> z_;
    int nTheta_;
    bool periodic_;
    double theta0_;
    double dTheta_;
    double ambient_ = 0.0;
    EdgeSpec edges_[4];
    // User overrides (fixNode/voidNode) survive edge changes; kinds are recomputed from them.
    std::vector<NodeKind> userKind_;   // Film = no override
    std::vector<double> userPressure_;
    std::vector<NodeKind> kind_;
    std::vector<double> fixedPressure_;
    // Column geometry (rad), per column j: control-volume width, covered width, face j | j + 1.
    std::vector<double> cvWidth_, coveredWidth_, coveredBelow_, faceAngle_;
    std::vector<double> cosTheta_, sinTheta_;  // per column j, of theta(j)
    std::vector<std::pair<double, double>> arcs_;
};

}  // namespace flexehd::lube
