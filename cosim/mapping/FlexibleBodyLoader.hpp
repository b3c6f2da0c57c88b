#pragma once
// Loads the reduced body a case names for the piston or the liner and sets it up as the film's
// FlexibleSurface, with every error naming the case file, the case key (bodies.piston.file,
// .surface, .interface) and the .h5 — not the mesh the body was once reduced from.
#include <memory>
#include <string>

#include "cosim/case/EngineCase.hpp"
#include "cosim/mapping/FlexibleSurface.hpp"

namespace flexehd::cosim {

/// body: the case's pistonBody or linerBody; role: "piston" or "liner" (the key
/// bodies.ROLE). zMin, zMax: as FlexibleSurface (liner). Throws std::invalid_argument
/// "CASE: bodies.ROLE.KEY: …" when the file cannot be read or does not hold the named surface
/// (a surface group) and interfaces, and when the surface cannot face the film.
std::unique_ptr<FlexibleSurface> loadFlexibleSurface(const EngineCase& c, const BodySpec& body, const std::string& role,
                                                     FlexibleSurface::Side side, const lube::FilmGrid& grid,
                                                     double zMin = 0.0, double zMax = 0.0);

}  // namespace flexehd::cosim
