#pragma once
// Reduced bodies built per variant of a study (`reduce.piston`, `reduce.liner` in the study
// file), cached by a content hash of their inputs — the `flexehd reduce` arguments and the
// bytes of the mesh file — so that variants with the same recipe share one file
// (STUDY_DIR/cache/BODY-HASH.h5). Which process builds them is the caller's business.
#include <string>
#include <vector>

#include "cosim/study/StudyFile.hpp"

namespace flexehd::cosim {

struct BodyBuild {
    std::string body;               ///< "piston" or "liner"
    std::string file;               ///< the cached reduced-body file (absolute)
    std::vector<std::string> args;  ///< `flexehd reduce` arguments without `--out`, canonical order
};

/// The reduced bodies of a variant: the study's recipes with the variant's `reduce.*` values.
/// Empty when the study has no recipes (the variant uses the base case's bodies).
std::vector<BodyBuild> variantBodies(const Study& study, const StudyVariant& variant);

/// 64-bit FNV-1a of a byte string, continuing from `hash`.
unsigned long long fnv1a64(const std::string& bytes, unsigned long long hash = 0xcbf29ce484222325ULL);

}  // namespace flexehd::cosim
