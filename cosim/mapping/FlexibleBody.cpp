#include "cosim/mapping/FlexibleBody.hpp"

#include <algorithm>
#include <stdexcept>

#include "modal/ModalSuperposition.hpp"

namespace flexehd::cosim {

namespace {
std::vector<int> heldIndices(const modal::ReducedBody& body, const std::vector<std::string>& held,
                             const std::string& what) {
    std::vector<int> out;
    std::string names;
    for (std::size_t i = 0; i < body.interfaces.size(); ++i) {
        names += (names.empty() ? "" : ", ") + body.interfaces[i].group;
        if (held.empty() || std::find(held.begin(), held.end(), body.interfaces[i].group) != held.end())
            out.push_back(int(i));
    }
    for (const std::string& h : held) {
        bool found = false;
        for (const auto& itf : body.interfaces) found = found || itf.group == h;
        if (!found)
            throw std::invalid_argument(what + ": interface '" + h + "' is not in the reduced body (it has: " +
                                        (names.empty() ? std::string("none") : names) + ")");
    }
    if (out.empty()) throw std::invalid_argument(what + ": the reduced body has no interface to hold");
    return out;
}
}  // namespace

FlexibleBody::FlexibleBody(modal::ReducedBody body, const std::vector<std::string>& held) : body_(std::move(body)) {
    const std::string what = body_.meshPath.empty() ? std::string("reduced body") : body_.meshPath;
    // Compliance with the held reference nodes fixed, C = N (Nᵀ K N)⁻¹ Nᵀ (once).
    held_ = heldIndices(body_, held, what);
    compliance_ = modal::ModalSuperposition(body_).compliance(held_);
}

}  // namespace flexehd::cosim
