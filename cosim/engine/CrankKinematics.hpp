#pragma once
// CrankKinematics: primary motion of the piston pin in a crank-slider mechanism with pin offset
// (docs/dynamics.md §1). Crank angle φ_c in degrees over the four-stroke cycle, 0° = gas-exchange
// TDC, 360° = firing TDC; the geometric crank angle is φ_c mod 360°. The crank pin sits at
// x = −r sin φ_c, z = r cos φ_c (crank axis at the origin), the piston pin at x = c (pin offset,
// positive towards the major thrust side +x), so the connecting rod makes the angle ψ with
//     sin ψ = (r sin φ_c + c) / l,
// and a rod in compression pushes the pin towards +x during expansion (360°–540°): +x is the
// major thrust side. (Some texts write sin φ = (r sin θ − c_pin)/l with the opposite sign of c.)

namespace flexehd::cosim {

struct CrankState {
    double position = 0.0;      ///< m, pin height above the crank axis
    double velocity = 0.0;      ///< m/s
    double acceleration = 0.0;  ///< m/s²
    double sinRod = 0.0;        ///< sin ψ
    double tanRod = 0.0;        ///< tan ψ
};

class CrankKinematics {
public:
    /// Throws std::invalid_argument unless stroke > 0, speed > 0 and rod > stroke/2 + |offset|.
    CrankKinematics(double stroke, double rodLength, double pinOffset, double speedRpm);

    CrankState at(double crankDeg) const;
    /// Pin height at TDC, √((l + r)² − c²) (rod and crank aligned).
    double tdcPosition() const;
    /// Crank angular speed, rad/s.
    double omega() const { return omega_; }
    /// Seconds per crank degree.
    double secondsPerDegree() const;
    double crankRadius() const { return r_; }

private:
    double r_, l_, c_, omega_;
};

}  // namespace flexehd::cosim
