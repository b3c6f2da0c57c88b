// SoundPowerLevel: dB re 1 pW (header).
#include "acoustics/SoundPowerLevel.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace flexehd::acoustics {

double soundPowerLevel_dB(double power_W) {
    if (!(std::isfinite(power_W) && power_W >= 0.0)) {
        std::ostringstream s;
        s << "power_W: expected a finite power ≥ 0 W, got " << power_W;
        throw std::invalid_argument(s.str());
    }
    return 10.0 * std::log10(power_W / kReferenceSoundPower_W);
}

}  // namespace flexehd::acoustics
