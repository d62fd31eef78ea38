// Private to core/: sliver exudation (RR-7912 section 6, [CDE+00]) on the
// triangulation left by Delaunay refinement.
//
// Vertices never move; each gets a weight in [w0, w0 + ratio * N(v)^2] (w0:
// its weight before, a protecting ball's or 0; N(v): the distance to its
// nearest neighbour), chosen by WeightPump to maximize the
// smallest dihedral angle of the cells of D|O around it. Vertices incident to
// a cell below the sliver bound are processed block by block of space
// (Morton order, sliver_queue_order.h) and worst first within a block (by the
// smallest dihedral angle of their incident domain cells); a vertex whose
// star changed is queued again. The smallest dihedral angle of the mesh never decreases:
// a move is applied only if it strictly raises the minimum over the cells it
// replaces.
//
// What holds after exudation (the triangulation is a regular triangulation
// with non-zero weights, `tr.is_valid()`):
//  - the restricted facets of D|S are the same vertex triples with the same
//    patch and surface center, stored on both incident cells as before;
//  - every cell's label is consistent with them (equal labels across a
//    non-restricted facet): the output mesh has the same boundary and the
//    same labelled regions, but a new cell's label is no longer the oracle's
//    label at its circumcenter, and a restricted facet's dual is no longer
//    its (weighted) Voronoi edge;
//  - CellInfo::circumcenter is not maintained, and every cell's
//    squared_radius holds its shape_cosine instead (they share storage);
//  - stamps of new cells are fresh (larger than every stamp before).
// Hence mesh extraction (labels and facet_patch) works unchanged, but
// refinement must not resume on the triangulation afterwards.
// VertexInfo::index is used as scratch (extraction resets it).
#pragma once

#include "../triangulation_types.h"
#include "chain_edges.h"
#include "rdmesh/criteria.h"
#include "rdmesh/optimization.h"

namespace rdmesh::detail {

/// Runs sliver exudation on `tr` (three-dimensional, labelled by refinement
/// with `criteria`, whose cell rules new cells keep as the options ask).
/// `chains`: the edges of D|L, which stay mesh edges (null: every edge joining
/// two feature vertices stays). `threads`: for the measures over all cells
/// (the result does not depend on it; 0: all cores).
ExudationStats exude_slivers(Triangulation& tr, const Criteria& criteria,
                             const ExudationOptions& options, const ChainEdges* chains = nullptr,
                             int threads = 1);

}  // namespace rdmesh::detail
