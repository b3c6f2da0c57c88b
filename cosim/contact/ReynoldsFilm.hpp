#pragma once
// ReynoldsFilm: the film with the Reynolds (Swift–Stieber) cavitation condition, solved by
// lube::ReynoldsSolver (multigrid, the active set where it stalls), the squeeze term the BDF2
// rate of the film thickness (docs/coupling.md §3) and the warm start the last accepted pressure.
#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmEquation.hpp"
#include "lube/ReynoldsSolver.hpp"

namespace flexehd::cosim {

class ReynoldsFilm final : public FilmEquation {
public:
    ReynoldsFilm(const EngineCase& c, const lube::FilmGrid& grid);

    void initialize(ContactState&) const override {}
    void solve(const ContactStep& step, const ContactState& now, const ContactState& before, ContactIterate& it,
               lube::FilmState& fs, WorkTally& work) override;
    void accept(const ContactStep&, const ContactState&, const ContactIterate&, ContactState&) const override {}
    double rateFactor(const ContactStep&) const override { return 1.0; }
    const lube::Lubricant& lubricant() const override { return solver_.lubricant(); }

private:
    bool elasticSqueeze_;
    lube::ReynoldsSolver solver_;
};

/// The case's lubricant as the film solvers take it.
lube::Lubricant makeLubricant(const LubricantSpec& l);

}  // namespace flexehd::cosim
