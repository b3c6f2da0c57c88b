#include "cosim/contact/CaseContacts.hpp"

#include "cosim/contact/SkirtContact.hpp"

namespace flexehd::cosim {

std::vector<std::unique_ptr<FilmContact>> caseContacts(const EngineCase& c, const CaseBodies& bodies,
                                                       const std::function<double(double)>& linerOffset) {
    std::vector<std::unique_ptr<FilmContact>> contacts;
    contacts.push_back(std::make_unique<SkirtContact>(c, bodies, linerOffset));
    return contacts;
}

}  // namespace flexehd::cosim
