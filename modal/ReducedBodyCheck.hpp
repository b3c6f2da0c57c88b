#pragma once
// The values a reduced body must have to be usable (docs/reduced-body-format.md, "Values"):
// every number finite, the material physical, the modal mass matrix symmetric positive
// definite, the modal stiffness symmetric and positive semi-definite, damping ratios and mesh
// size non-negative. The reader applies it to every file, `flexehd inspect` therefore too.
#include <optional>
#include <string>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

/// The first defect found, naming the dataset or attribute of the file layout
/// (e.g. "dataset /modes/shapes has a non-finite value (nan) at [4, 17]"); empty when none.
/// Sizes are not checked here (the reader checks them against the mesh while reading).
std::optional<std::string> reducedBodyDefect(const ReducedBody& body);

}  // namespace flexehd::modal
