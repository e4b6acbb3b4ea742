#pragma once
// Repair of real-world inputs before the remeshing: what scanners, surface
// reconstructions and CAD or game-asset exporters produce and the strict input check
// (mesh_check.h) refuses or keeps as broken pieces. Every step is counted in RepairReport.
// Linear in the input: hashes of coordinates, faces and grid cells, one edge table, union-finds.
//
// In this order:
//  1. vertices at exactly the same coordinates merged; border vertices (on an edge with one
//     face) closer than weldTolerance × the mean edge length merged (cracks, seams); a border
//     vertex that close to the inside of a border edge inserted into it (T-junctions). Vertices
//     joined by an edge are never merged, and nothing farther apart than the tolerance is: a
//     real gap stays open;
//  2. faces with a repeated corner or no area removed; duplicate faces (same corners, same
//     orientation) and opposite duplicates (same corners, reversed) removed, the first kept;
//  3. non-manifold edges (more than two faces) resolved: around the edge the faces are paired
//     into manifold sheets (consecutive faces around the edge that enclose the same side), the
//     others get a border there; the surface is split along the edge;
//  4. non-orientable components cut along the edges where the orientation of a breadth-first
//     walk disagrees (a seam), so that every piece is orientable;
//  5. vertices whose faces form several fans (non-manifold vertices, the ends of the cuts) split
//     into one vertex per fan;
//  6. connected components too small for the vertex budget (fewer than minComponentSamples
//     expected samples, less than keepAreaFraction of the area, and not a part of its own far
//     from the rest: RepairParams::farComponentEdges) dropped; none left throws
//     InvalidInputError saying how many vertices would keep the largest.
// An input with an out-of-range index or a non-finite coordinate is returned as it is, for the
// strict check to refuse with its message.
#include "mesh.h"
#include "mesh_check.h"
#include "repair_params.h"

#include <string>
#include <vector>

namespace fieldcvt {

//! The repaired copy of `input` (see the top of this file).
TriMesh repairMesh(const TriMesh& input, const RepairParams& params, RepairReport& report);

//! repairMesh, then prepareInput on the result (as repaired: without its exact-duplicate merge,
//! which would undo the splits, nor its duplicate-face search); `input` of
//! InputReport::cleanIndex is the original input. Repair notes come first in InputReport::notes.
TriMesh repairAndPrepare(const TriMesh& input, const RepairParams& params, RepairReport& repair, InputReport& report);

}  // namespace fieldcvt
