#pragma once
// CouplingNeeds: what the step's coupling scheme asks of the film contacts beyond their film and
// loads (docs/coupling.md §1) — told to each contact once, before its first step
// (FilmContact::prepare).

namespace flexehd::cosim {

struct CouplingNeeds {
    /// The coupled Newton scheme's modal Jacobian: the contacts' load change with the modal
    /// coordinates (FilmContact::linearize; docs/coupling.md §3).
    bool modalJacobian = false;
};

}  // namespace flexehd::cosim
