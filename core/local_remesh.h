#pragma once
// Isotropic remeshing by local operations (Botsch & Kobbelt 2004: split long edges, collapse
// short ones, flip edges, tangential smoothing projected on the surface) on the input's own
// connectivity. Unlike the restricted Delaunay triangulation of the optimised samples, which can
// lose a handle, open a hole or merge parts where the surface is thinner than an edge, every
// operation here keeps the topology: each selected component comes out as one component of the
// same genus with the same border loops. remesh_topology.cpp uses it on the shells where the RDT
// got the topology wrong; the valence optimisation then runs on the whole output, hence the
// roles and face hints of the result.
#include "closest_point.h"
#include "mesh.h"
#include "strip_sizing.h"
#include "valence/surface.h"

#include <array>
#include <vector>

namespace fieldcvt {

struct LocalRemeshParams {
    //! Target edge length (working units, remesh_stages.h: kWorkingEdgeLength). Edges longer than
    //! 4/3 of it are split, shorter than 4/5 of it collapsed.
    double targetLength = 1.0746;
    //! Rounds of split / collapse / flip / smoothing.
    int iterations = 10;
    //! Shorter edges on strips between two creases narrower than the target length (a CAD part's
    //! rims, steps, small holes), graded back around them: triangles there that span the strip
    //! and keep both creases without being slivers (strip_sizing.h).
    bool refineStrips = true;
    StripSizingParams strips;
};

struct LocalRemeshInput {
    const TriMesh& surface;                  //!< manifold, oriented (several components and open borders allowed)
    const ClosestPointTree& tree;            //!< of `surface`
    const std::vector<char>& selectedFaces;  //!< per surface face: remesh it (whole components); the rest is left out
    //! Feature edges (surface vertex pairs, smaller first, sorted): kept as chains of output
    //! edges. Pairs that are no edge of a selected face, or that lie on the open border (kept
    //! anyway), are ignored.
    std::vector<std::array<int, 2>> featureEdges;
    std::vector<int> corners;  //!< surface vertices kept exactly (sorted); ends and branches of the lines are added
    //! Target edge length per surface face (working units), e.g. shorter on thin parts; empty:
    //! LocalRemeshParams::targetLength everywhere.
    std::vector<double> targetLengthPerFace;
};

struct LocalRemeshResult {
    TriMesh mesh;                      //!< the selected components remeshed, same orientation
    std::vector<VertexRole> roles;     //!< per output vertex: Boundary (open border), Feature, Corner or Free
    std::vector<int> vertexFaceHints;  //!< per output vertex: the surface face of its closest point
    int splits = 0, collapses = 0, flips = 0;
};

//! Remeshes the selected components of `input.surface`. Only edge splits, collapses that keep
//! the link condition (and the border loops, the feature chains, a closed component's four
//! vertices) and flips of interior non-feature edges are used, so every component keeps its
//! genus and border loops and the output is manifold and oriented. Vertices stay on their own
//! sheet of the surface (a projection onto the far side of a thin plate is refused), border
//! vertices on their loop, feature vertices on their line, corners where they are.
//! Deterministic whatever the thread count.
//! \throw InvalidInputError if the mask or the per-face lengths do not match the surface, a
//! length is not positive, an index is out of range, or the selected faces are not a manifold,
//! oriented surface.
LocalRemeshResult remeshLocally(const LocalRemeshInput& input, const LocalRemeshParams& params);

}  // namespace fieldcvt
