#pragma once
// The case file of one variant of a study: the base case with the study's fixed values and
// the variant's values set by dotted key, relative paths made absolute, and the reduced
// bodies built for the variant in place of the base case's (docs/sweep.md).
#include <map>
#include <string>

#include "cosim/study/StudyFile.hpp"

namespace flexehd::cosim {

/// The variant's case file as YAML text. `bodyFiles` maps "piston" / "liner" to the
/// reduced-body file built for the variant (empty: the base case's bodies). Deterministic:
/// the same study and variant give the same text, which is how a resumed study recognises
/// a variant it has already run. Throws naming the key if a key passes through a value of
/// the base case that is not a mapping.
std::string variantCaseText(const Study& study, const StudyVariant& variant,
                            const std::map<std::string, std::string>& bodyFiles = {});

/// Checks that every `set` key and parameter of the study names a case-file key (reading the
/// base case with that one key set, through readCaseFile). Throws "STUDY: parameters.KEY: not
/// a case-file key: …" with the case reader's reason. Out-of-range values are not errors
/// here: they fail their variant.
void checkCaseKeys(const Study& study);

}  // namespace flexehd::cosim
