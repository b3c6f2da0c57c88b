#pragma once
// Rings for the ring-contact tests: the small engine with asperities that carry a ring's tension,
// and a barrel-faced compression ring.
#include "cosim/case/EngineCase.hpp"

#include "SmallEngineCase.hpp"

namespace flexehd::test {

// The case: the small engine with asperities that carry a ring's tension at a positive gap
// (the example's β and η_s, a steel ring on a cast-iron liner).
inline cosim::EngineCase ringCase() {
    cosim::EngineCase c = smallCase();
    c.contact.beta = 0.6e-3;
    c.contact.asperityDensity = 1.111e8;
    c.contact.compositeModulus = 1.0e11;
    return c;
}

// A barrel-faced compression ring of height b, crown c (vertex radius (b/2)²/(2c)), tension T (N/m).
inline cosim::RingSpec barrelRing(double b, double c, double T, double roughness) {
    cosim::RingSpec r;
    r.name = "test";
    r.kind = cosim::RingKind::Compression;
    r.height = b;
    r.radialWidth = 3e-3;
    r.face.crownHeight = c;
    r.tensionPerLength = T;
    r.closedGap = 0.25e-3;
    r.mass = 7e-3;
    r.roughness = roughness;
    r.groove = {0.0253, 0.05e-3, 0.6e-3};
    return r;
}

}  // namespace flexehd::test
