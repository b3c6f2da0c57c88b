#pragma once
// CaseContacts: the film contacts a case names, built for the master in the order it iterates
// over them — the skirt's film (SkirtContact) first (docs/coupling.md §1, "Film contacts").
#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace flexehd::cosim {

/// bodies: the case's flexible bodies (null when rigid), shared by the contacts' surfaces;
/// linerOffset(crank angle in degrees): the liner-frame z of the piston frame's origin.
std::vector<std::unique_ptr<FilmContact>> caseContacts(const EngineCase& c, const CaseBodies& bodies,
                                                       const std::function<double(double)>& linerOffset);

}  // namespace flexehd::cosim
