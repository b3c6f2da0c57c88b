#include "modal/ModalDamping.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace flexehd::modal {

DampingBand parseDampingBand(const std::string& text) {
    std::stringstream s(text);
    DampingBand b;
    char colon = 0;
    if (!(s >> b.upToHz >> colon >> b.ratio) || colon != ':' || !s.eof())
        throw std::invalid_argument("damping band '" + text + "': expected FMAX:ZETA, e.g. 5000:0.02");
    if (!(b.upToHz > 0.0) || !(b.ratio >= 0.0 && b.ratio < 1.0))
        throw std::invalid_argument("damping band '" + text + "': need FMAX > 0 Hz and 0 <= ZETA < 1");
    return b;
}

void assignModalDamping(ReducedBody& body, double defaultRatio, std::vector<DampingBand> bands) {
    if (!(defaultRatio >= 0.0 && defaultRatio < 1.0))
        throw std::invalid_argument("damping ratio must lie in [0, 1)");
    std::sort(bands.begin(), bands.end(), [](auto& a, auto& b) { return a.upToHz < b.upToHz; });
    body.dampingRatios.resize(body.numModes());
    for (int k = 0; k < body.numModes(); ++k) {
        double z = defaultRatio;
        for (const auto& b : bands)
            if (body.frequenciesHz(k) <= b.upToHz) {
                z = b.ratio;
                break;
            }
        body.dampingRatios(k) = body.rigidBody[k] ? 0.0 : z;
    }
}

Eigen::VectorXd modalDampingCoefficients(const ReducedBody& body) {
    const Eigen::Index m = body.numModes();
    Eigen::VectorXd c(m);
    for (Eigen::Index k = 0; k < m; ++k)
        c(k) = 2.0 * body.dampingRatios(k) * std::sqrt(std::max(body.stiffnessMatrix(k, k), 0.0));
    return c;
}

Eigen::MatrixXd bodyDampingMatrix(const ReducedBody& body) {
    Eigen::MatrixXd C = modalDampingCoefficients(body).asDiagonal();
    if (hasSupportDamping(body)) {
        if (body.supportDamping.rows() != C.rows() || body.supportDamping.cols() != C.cols())
            throw std::invalid_argument("reduced body: support damping is " + std::to_string(body.supportDamping.rows()) +
                                        " x " + std::to_string(body.supportDamping.cols()) + " for " +
                                        std::to_string(C.rows()) + " modes");
        C += body.supportDamping;
    }
    return C;
}

}  // namespace flexehd::modal
