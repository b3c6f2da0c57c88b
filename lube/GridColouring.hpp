#pragma once
// A distance-2 colouring of a film grid: nodes of one colour are at least three grid steps apart,
// so no balance row (a node and its four neighbours) depends on two of them. Perturbing the
// thickness of one colour at a time gives a row's derivatives in all its nodes from one
// evaluation per colour — the sparse finite-difference Jacobians of FilmLinearization and
// JfoLinearization (Curtis, Powell & Reid, J. Inst. Maths Applics 13 (1974) 117).
#include <vector>

#include "lube/FilmGrid.hpp"

namespace flexehd::lube {

/// The grid neighbours of node k (θ wrapped on a full circumference).
template <class Visit>
void forEachNeighbour(const FilmGrid& g, int k, Visit&& visit) {
    const int nz = g.nAxial(), nt = g.nTheta(), i = g.axialIndex(k), j = g.thetaIndex(k);
    if (i > 0) visit(g.index(i - 1, j));
    if (i + 1 < nz) visit(g.index(i + 1, j));
    if (j > 0 || g.periodic()) visit(g.index(i, (j + nt - 1) % nt));
    if (j + 1 < nt || g.periodic()) visit(g.index(i, (j + 1) % nt));
}

struct GridColouring {
    std::vector<int> colour;  ///< per node
    int colours = 0;          ///< number of colours
};

/// Greedy distance-2 colouring: a node takes the smallest colour not used within two steps.
GridColouring distanceTwoColouring(const FilmGrid& grid);

}  // namespace flexehd::lube
