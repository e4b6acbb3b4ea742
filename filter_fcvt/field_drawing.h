#pragma once
// A drawable picture of a 6-RoSy field for MeshLab: an edge mesh (vertices + edges, no faces)
// with three segments through each drawn vertex along the six field directions. Presentation
// only: the field itself comes from the core (fieldcvt::computeField).
#include "meshlab_types.h"

#include "field.h"
#include "mesh.h"

namespace fcvt_plugin {

struct FieldDrawingStats {
    int drawnVertices = 0;       //!< vertices of `mesh` that got their three segments
    int stride = 1;              //!< every stride-th vertex is drawn (1 = all)
    double segmentLength = 0;    //!< total length of each segment (mesh units)
    double meanEdgeLength = 0;   //!< of `mesh`, over its face edges
};

//! Replaces the content of `out` with the drawing of `field` on `mesh`: at every vertex (every
//! stride-th one, stride = ceil(vertexCount / maxPoints), when the mesh has more than maxPoints
//! vertices) three segments centred on the vertex, along d and d rotated by 60° and 120° about
//! n, so that their six half-segments are the six field directions. Each segment is about half
//! the mean edge length long (times sqrt(stride) on a subset, so the drawing keeps its look).
//! Segment s of drawn vertex i uses vertices 6i + 2s (towards +direction) and 6i + 2s + 1
//! (towards −direction) and edge 3i + s. Vertex normals = field normals; vertex colours set.
FieldDrawingStats drawField(const fieldcvt::TriMesh& mesh, const fieldcvt::DirectionField& field, CMeshO& out,
                            int maxPoints = 20000);

}  // namespace fcvt_plugin
