#pragma once
// The one way a reader opens a YAML file (case, study, thermal case, a study's base case): the
// whole file as text with lone-CR line ends taken as LF, a NUL byte refused with its line, a YAML
// syntax error as "FILE:LINE:COL: YAML syntax error: ...", and one document only.
#include <string>

#include <yaml-cpp/yaml.h>

namespace flexehd::cosim {

/// The single YAML document of the file `path`. `what` names the file in messages ("the case
/// file", "the study file"). Throws std::runtime_error, each message beginning with `path`:
/// "cannot read WHAT: REASON", "WHAT contains a NUL byte at line N", "LINE:COL: YAML syntax
/// error", "WHAT holds N YAML documents", "WHAT is empty". A UTF-8 byte-order mark is skipped.
YAML::Node loadYamlDocument(const std::string& path, const std::string& what);

}  // namespace flexehd::cosim
