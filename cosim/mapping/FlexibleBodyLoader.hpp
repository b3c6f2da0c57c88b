#pragma once
// Loads the reduced bodies a case names for the piston and the liner, and sets one up as a film's
// FlexibleSurface, with every error naming the case file, the case key (bodies.piston.file,
// .surface, .interface) and the .h5 — not the mesh the body was once reduced from.
#include <memory>
#include <string>

#include "cosim/case/EngineCase.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/mapping/FlexibleSurface.hpp"

namespace flexehd::cosim {

/// The flexible bodies of a case (null: rigid), read once and shared by every contact's surfaces.
struct CaseBodies {
    std::shared_ptr<const FlexibleBody> piston, liner;
};

/// Reads the bodies the case names flexible (bodies.piston, bodies.liner). Throws
/// std::invalid_argument "CASE: bodies.ROLE.KEY: …" when a file cannot be read or does not hold the
/// named surface (a surface group) and interfaces.
CaseBodies loadCaseBodies(const EngineCase& c);

/// Film nodes outside a surface's image beyond which facingSurface refuses the body (fraction of
/// the grid's film nodes).
inline constexpr double kMaxOutsideFraction = 0.25;

/// The body (of the case's body spec; role "piston" or "liner", the key bodies.ROLE) seen from a
/// film's grid. zMin, zMax: as FlexibleSurface (liner). Throws std::invalid_argument
/// "CASE: bodies.ROLE.surface: …" when the surface cannot face the film, faces it from the other
/// role's side (a liner's bore as the piston's surface, a skirt as the liner's), or misses more than
/// kMaxOutsideFraction of the grid's film nodes (saying how many, how far, and what the case expects).
std::unique_ptr<FlexibleSurface> facingSurface(const EngineCase& c, std::shared_ptr<const FlexibleBody> body,
                                               const BodySpec& spec, const std::string& role,
                                               FlexibleSurface::Side side, const lube::FilmGrid& grid,
                                               double zMin = 0.0, double zMax = 0.0);

}  // namespace flexehd::cosim
