#include "cosim/ringpack/OrificeFlow.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

namespace {

constexpr double kLinearBelow = 1e-4;  // 1 − r below which the flow is a quadratic in Δp

// ψ(r) = √(r^{2/γ} − r^{(γ+1)/γ}) and dψ/dr.
double psi(double g, double r, double* dr) {
    const double a = std::pow(r, 2.0 / g), b = std::pow(r, (g + 1.0) / g), s = std::sqrt(std::max(a - b, 0.0));
    if (dr) *dr = s > 0.0 ? ((2.0 / g) * a / r - ((g + 1.0) / g) * b / r) / (2.0 * s) : 0.0;
    return s;
}

// Flow from the upstream side (pu, tu) to pd ≤ pu, its derivatives in pu and pd.
double downhill(const GasProperties& gas, double cda, double pu, double pd, double tu, double& dpu, double& dpd) {
    const double g = gas.gamma, k = cda * std::sqrt(2.0 * g / ((g - 1.0) * gas.gasConstant * tu));
    const double rs = criticalPressureRatio(gas);
    double r = pd / pu;
    if (r <= rs) {  // choked: ψ(r*) p_u
        dpd = 0.0;
        dpu = k * psi(g, rs, nullptr);
        return dpu * pu;
    }
    if (1.0 - r < kLinearBelow) {
        // ṁ = A Δp + B Δp²/p_u, Δp = p_u − p_d: finite slope at Δp = 0, and the law's value and
        // slope at r1 = 1 − kLinearBelow (Δp1 = kLinearBelow p_u), so that the flow is C¹ there.
        const double e = kLinearBelow, r1 = 1.0 - e;
        double d1 = 0.0;
        const double psi1 = psi(g, r1, &d1);
        const double s1 = -k * d1;  // the law's ∂ṁ/∂Δp at r1 (p_u held)
        const double a = 2.0 * k * psi1 / e - s1, b = (s1 * e - k * psi1) / (e * e);
        const double dp = pu - pd, q = dp / pu;
        dpd = -(a + 2.0 * b * q);
        dpu = a + 2.0 * b * q - b * q * q;
        return a * dp + b * dp * q;
    }
    double dr = 0.0;
    const double s = psi(g, r, &dr);
    dpd = k * dr;                 // ∂(k p_u ψ(p_d/p_u))/∂p_d
    dpu = k * (s - r * dr);       // ∂/∂p_u
    return k * pu * s;
}

}  // namespace

double criticalPressureRatio(const GasProperties& gas) {
    return std::pow(2.0 / (gas.gamma + 1.0), gas.gamma / (gas.gamma - 1.0));
}

double orificeFlow(const GasProperties& gas, double cda, double pa, double pb, double ta, double tb, double* dpa,
                   double* dpb) {
    if (!(pa > 0.0) || !(pb > 0.0) || !(ta > 0.0) || !(tb > 0.0) || !(cda >= 0.0) || !std::isfinite(pa + pb + ta + tb + cda))
        throw std::invalid_argument("orifice flow: pressures (" + std::to_string(pa) + ", " + std::to_string(pb) +
                                    " Pa) and temperatures must be positive and the area >= 0");
    double du = 0.0, dd = 0.0, m = 0.0;
    if (pa >= pb) {
        m = downhill(gas, cda, pa, pb, ta, du, dd);
        if (dpa) *dpa = du;
        if (dpb) *dpb = dd;
        return m;
    }
    m = downhill(gas, cda, pb, pa, tb, du, dd);
    if (dpa) *dpa = -dd;
    if (dpb) *dpb = -du;
    return -m;
}

double channelFlow(const GasProperties& gas, double conductance, double limitArea, double pa, double pb, double ta,
                   double tb, double* dpa, double* dpb) {
    if (!(pa > 0.0) || !(pb > 0.0) || !(ta > 0.0) || !(tb > 0.0) || !(conductance >= 0.0) || !(limitArea >= 0.0) ||
        !std::isfinite(pa + pb + ta + tb + conductance + limitArea))
        throw std::invalid_argument("channel flow: pressures (" + std::to_string(pa) + ", " + std::to_string(pb) +
                                    " Pa) and temperatures must be positive, the conductance and area >= 0");
    if (dpa) *dpa = 0.0;
    if (dpb) *dpb = 0.0;
    if (conductance == 0.0) return 0.0;
    const double t = pa >= pb ? ta : tb;
    const double k = conductance / (24.0 * gas.viscosity * gas.gasConstant * t);
    double m = k * (pa * pa - pb * pb), da = 2.0 * k * pa, db = -2.0 * k * pb;
    if (limitArea > 0.0) {  // in series with the orifice: the resistances add, m = m_c m_o/(m_c + m_o)
        double oa = 0.0, ob = 0.0;
        const double o = orificeFlow(gas, limitArea, pa, pb, ta, tb, &oa, &ob), sum = m + o;
        if (sum != 0.0) {
            da = (o * o * da + m * m * oa) / (sum * sum);
            db = (o * o * db + m * m * ob) / (sum * sum);
            m = m * o / sum;
        } else {  // equal pressures: the slopes in series
            da = da + oa != 0.0 ? da * oa / (da + oa) : 0.0;
            db = db + ob != 0.0 ? db * ob / (db + ob) : 0.0;
        }
    }
    if (dpa) *dpa = da;
    if (dpb) *dpb = db;
    return m;
}

}  // namespace flexehd::cosim
