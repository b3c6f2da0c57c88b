#pragma once
// Lubricant: viscosity η(p) and density ρ(p) of the oil at the film temperature.
//
// Viscosity models (p gauge pressure in Pa, η in Pa·s):
//   Constant:  η = η0
//   Barus:     η = η0 exp(α p)
//   Roelands:  η = η0 exp{(ln η0 + 9.67)[(1 + p/p_R)^Z − 1]},  p_R = 1.96e8 Pa,
//              Z = α p_R / (ln η0 + 9.67) so that both models share the low-pressure slope α
//              (Roelands 1966; the constant 9.67 = −ln(6.31e-5 Pa·s)).
// Density models:
//   Constant:           ρ = ρ0
//   Dowson–Higginson:   ρ = ρ0 [1 + 0.6e-9 p / (1 + 1.7e-9 p)]   (Dowson & Higginson 1966)
// Negative (sub-ambient) pressures are clamped to 0 in the pressure-dependent laws.
namespace flexehd::lube {

enum class ViscosityModel { Constant, Barus, Roelands };
enum class DensityModel { Constant, DowsonHigginson };

class Lubricant {
public:
    /// Constant viscosity η0 (Pa·s) and density ρ0 (kg/m³); both must be positive.
    Lubricant(double viscosity, double density = 850.0);

    /// Pressure–viscosity law with coefficient α (1/Pa, typically 1e-8 to 2.5e-8).
    Lubricant& withBarus(double alpha);
    Lubricant& withRoelands(double alpha);
    Lubricant& withDowsonHigginson();

    double viscosity(double p) const;
    double density(double p) const;
    double referenceViscosity() const { return eta0_; }
    double referenceDensity() const { return rho0_; }
    double pressureViscosityCoefficient() const { return alpha_; }
    ViscosityModel viscosityModel() const { return viscosityModel_; }
    DensityModel densityModel() const { return densityModel_; }
    bool pressureDependent() const {
        return viscosityModel_ != ViscosityModel::Constant ||
               densityModel_ != DensityModel::Constant;
    }

    static constexpr double kRoelandsPressure = 1.96e8;

private:
    double eta0_;
    double rho0_;
    double alpha_ = 0.0;
    double roelandsZ_ = 0.0;
    ViscosityModel viscosityModel_ = ViscosityModel::Constant;
    DensityModel densityModel_ = DensityModel::Constant;
};

}  // namespace flexehd::lube
