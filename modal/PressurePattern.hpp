#pragma once
// PressurePattern: a uniform-pressure static-correction pattern of `flexehd reduce
// --pressure-pattern` (docs/modal.md, "Uniform-pressure patterns"): a surface group, or the part
// of it whose triangles have their centroid in a band of the body's axial coordinate z, written
//
//   GROUP              e.g. crown
//   GROUP@ZLOW:ZHIGH   e.g. ring_grooves@0.02529:0.02531 (m, mesh frame; either bound may be
//                      left out: ring_lands@0.0265: is the group above z = 0.0265 m)
//
// so that one group (a piston's ring lands or grooves) gives a pattern per land or groove flank.
#include <limits>
#include <string>

#include "fem/BoundarySurface.hpp"
#include "fem/Mesh.hpp"

namespace flexehd::modal {

struct PressurePattern {
    std::string group;
    double zLow = -std::numeric_limits<double>::infinity();
    double zHigh = std::numeric_limits<double>::infinity();

    /// Throws std::invalid_argument naming the text and the expected form.
    static PressurePattern parse(const std::string& text);
    /// The pattern as `reduce` takes it (bounds to 9 significant digits).
    std::string text() const;
    bool banded() const { return zLow > -std::numeric_limits<double>::infinity() || zHigh < std::numeric_limits<double>::infinity(); }
    /// The same group and bounds within `tolerance` (m; open bounds match open bounds).
    bool matches(const PressurePattern& other, double tolerance) const;
    /// Its triangles on the mesh (throws std::invalid_argument for an unknown group or an empty band).
    fem::BoundarySurface surface(const fem::Mesh& mesh) const { return fem::BoundarySurface(mesh, group, zLow, zHigh); }
};

}  // namespace flexehd::modal
