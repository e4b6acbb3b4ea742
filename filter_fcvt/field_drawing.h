#pragma once
// A drawable picture of a 6-RoSy field for MeshLab: a cross of three thin strips through each
// drawn vertex along the six field directions. Presentation only: the field itself comes from the
// core (fieldcvt::computeField).
//
// Why strips (two triangles each) and not edges: MeshLab 2020.09 draws every vertex of a layer
// without faces as a point square (MLPoliciesStandAloneFunctions::suggestedDefaultPerViewRenderingData
// always turns PR_POINTS on for it), and on a dense mesh those squares at the segment ends cover
// the model; a layer with faces is drawn solid, without points, by default.
#include "meshlab_types.h"

#include "field.h"
#include "mesh.h"

namespace fcvt_plugin {

//! The strips' colour: amber, apart from MeshLab's grey surface and dark wireframe and from the
//! valence palette (blue, white, pink).
inline const vcg::Color4b kFieldColour(255, 170, 0, 255);

struct FieldDrawingStats {
    int drawnVertices = 0;         //!< vertices of `mesh` that got a cross
    double spacing = 0;            //!< grid cell of the subset (0: every vertex drawn)
    double meanSegmentLength = 0;  //!< mean over the crosses of a segment's length (mesh units)
    double meanEdgeLength = 0;     //!< of `mesh`, over its face edges
};

//! Strip geometry relative to a cross's segment length L (see drawField).
constexpr double kSegmentPerEdge = 0.6;  //!< L = 0.6 x the local edge length ...
constexpr double kSegmentPerCell = 0.6;  //!< ... or 0.6 x the subset's grid cell, the larger
constexpr double kStripWidth = 0.12;     //!< width of a strip, x L
constexpr double kLift = 0.15;           //!< height of the cross above the vertex along n, x L

//! Replaces the content of `out` with the drawing of `field` on `mesh`. At most `maxCrosses`
//! crosses: every vertex when the mesh has no more, otherwise one vertex per cell of a uniform
//! grid (the first in index order), the cell grown by 10 % steps from sqrt(area / maxCrosses)
//! until at most maxCrosses cells hold a vertex. A cross at vertex p with normal n is three
//! strips centred on p + kLift L n (lifted off the surface, so that on a curved surface the arms
//! do not sink into it), along d and d turned by 60 and 120 degrees about n, so that their six
//! half-strips are the six field directions; L = max(kSegmentPerEdge x the mean length of the
//! vertex's edges, kSegmentPerCell x the grid cell). Strip s of cross i: vertices 12i + 4s ..
//! 12i + 4s + 3 (end -d: -w, end +d: -w, end +d: +w, end -d: +w, with w = n x d), faces 6i + 2s
//! and 6i + 2s + 1, facing n. Vertex normals = n, vertex colours kFieldColour.
FieldDrawingStats drawField(const fieldcvt::TriMesh& mesh, const fieldcvt::DirectionField& field, CMeshO& out, int maxCrosses);

}  // namespace fcvt_plugin
