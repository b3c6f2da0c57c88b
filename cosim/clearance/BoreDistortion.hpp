#pragma once
// BoreDistortion: the liner's assembly distortion (head bolts, gasket) as a radial displacement
// Δr(z, θ) of the bore in the liner frame. It is part of the rigid clearance (seed eq. 2):
// h += Δr, outward distortion opens the gap. Two sources (docs/case-file.md `liner`):
//
//  * Fourier orders per axial position (the usual measurement format):
//        Δr(z_k, θ) = Σ_n A_n(z_k) cos(n (θ − φ_n(z_k)))
//    at the table's positions z_k; an order missing at a position has A_n = 0 there. Between
//    positions Δr is linear in z (the field, i.e. A_n cos nφ_n and A_n sin nφ_n, is interpolated,
//    not amplitude and phase, so the phase never wraps), and constant beyond the first and last.
//  * Nodal displacements of an external FE result on the bore (CSV or .vtu; x, y, z and u_x, u_y,
//    u_z, or u_r): the radial component u_r = u_x cos θ + u_y sin θ at each bore node, fitted at every
//    point of a liner-fixed grid by a moving least-squares quadratic in (z, R θ) over the 24
//    nearest bore nodes (Wendland weight, support = the 24th node's distance): reproduces
//    quadratics in (z, Rθ) exactly and is continuous.
//
// Both become a LinerFieldTable (liner-frame rows × film θ columns), sampled at the piston's
// position each step. The Fourier table is exact there (its rows are the measurement positions).

#include "cosim/case/EngineCase.hpp"
#include "cosim/clearance/LinerFieldTable.hpp"
#include "lube/FilmGrid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace flexehd::cosim {

/// Reads a Fourier distortion table (CSV; comma, semicolon or blanks; `#` comments). The first
/// line is a header naming the four columns, in any order: `z` (m, liner frame: 0 at the liner
/// top face, negative down the bore) or `depth` (m below the top face, z = −depth); `order`;
/// `amplitude` (m, radial); `phase` (rad) or `phase_deg` (degrees). Terms are checked with
/// checkFourierTerms and returned sorted. Errors: std::runtime_error "FILE:LINE: reason".
std::vector<FourierTerm> readFourierTable(const std::string& path, double bore);

struct TermProblem {
    std::size_t index = 0;  ///< the term at fault (of the vector as given)
    std::string message;
    std::size_t first = 0;  ///< for an order given twice: its first occurrence
};
/// The first problem of a term list: an order outside 0 … 100, an amplitude above 1 % of the
/// bore (units), an order given twice at one position, no term at all.
std::optional<TermProblem> checkFourierTerms(const std::vector<FourierTerm>& terms, double bore);
/// Sorts by z, then order.
void sortFourierTerms(std::vector<FourierTerm>& terms);
/// Δr(z, θ) of the (sorted) terms, linear in z between positions, constant beyond (m).
double fourierDistortion(const std::vector<FourierTerm>& terms, double z, double theta);

/// Reads the nodes of an FE displacement result: a CSV with a header (columns `x`, `y`, `z` (m,
/// liner frame) and either `ux`, `uy`, `uz` or `ur` (m); other columns, e.g. node ids, ignored)
/// or a VTK .vtu file (points in m, liner frame; the point-data array `field`: 3 components u or
/// 1 component u_r, m). Keeps the bore nodes: those within 1e-3 · bore/2 of the innermost radius,
/// which must lie within 1 % of bore/2. Errors: std::runtime_error "FILE[:LINE]: reason".
std::vector<BoreNode> readBoreNodes(const std::string& path, double bore, const std::string& field = "displacement");
/// True for a path ending in .vtu (any case): read as VTK XML, otherwise as CSV.
bool isVtuFile(const std::string& path);

/// The distortion tabulated for `grid`'s θ columns. Fourier: rows at the table's positions.
LinerFieldTable fourierDistortionTable(const std::vector<FourierTerm>& terms, const lube::FilmGrid& grid,
                                       std::string name);
/// Nodal: rows uniform over [zMin, zMax] (liner frame) with spacing ≤ min(half the grid's axial
/// spacing, 0.5 mm). Throws std::runtime_error naming `name` if the bore nodes do not cover
/// [zMin, zMax] axially.
LinerFieldTable nodalDistortionTable(const std::vector<BoreNode>& nodes, const lube::FilmGrid& grid, double zMin,
                                     double zMax, std::string name);

}  // namespace flexehd::cosim
