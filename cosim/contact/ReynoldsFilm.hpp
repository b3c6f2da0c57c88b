#pragma once
// ReynoldsFilm: the film with the Reynolds (Swift–Stieber) cavitation condition, solved by
// lube::ReynoldsSolver (multigrid, the active set where it stalls), the squeeze term the BDF2
// rate of the film thickness (docs/coupling.md §3) and the warm start the last accepted pressure;
// its linearisation the cavitated set held (lube::FilmLinearization).
#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmEquation.hpp"
#include "lube/FilmLinearization.hpp"
#include "lube/ReynoldsSolver.hpp"

#include <memory>

namespace flexehd::cosim {

class ReynoldsFilm final : public FilmEquation {
public:
    ReynoldsFilm(const EngineCase& c, const lube::FilmGrid& grid);

    void initialize(ContactState&) const override {}
    void solve(const ContactStep& step, const ContactState& now, const ContactState& before, ContactIterate& it,
               lube::FilmState& fs, WorkTally& work) override;
    void accept(const ContactStep&, const ContactState&, const ContactIterate&, ContactState&) const override {}
    void linearize(const ContactStep& step, const ContactState& now, const ContactIterate& it) override;
    Eigen::MatrixXd pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const override;
    Eigen::MatrixXd rateChange(const ContactStep& step, const Eigen::MatrixXd& dhs) const override;
    const lube::Lubricant& lubricant() const override { return solver_.lubricant(); }

private:
    bool elasticSqueeze_;
    lube::ReynoldsSolver solver_;
    std::unique_ptr<lube::FilmLinearization> linearization_;  // built on the first linearize
    double cavitationPressure_;
};

/// The case's lubricant as the film solvers take it.
lube::Lubricant makeLubricant(const LubricantSpec& l);

}  // namespace flexehd::cosim
