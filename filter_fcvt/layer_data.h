#pragma once
// What the filters read from and write to MeshLab layers besides the geometry: point conversions,
// the per-vertex "rosy" attribute, the output layer's name, valence colours, the selection's
// border as feature lines, and the input's per-vertex data carried to the output.
#include <QString>

#include <array>
#include <vector>

#include "meshlab_types.h"
#include "mesh.h"

namespace fcvt_plugin {

fieldcvt::Vec3 toVec3(const Point3m& p);
Point3m toPoint3m(const fieldcvt::Vec3& v);

//! A handle to the per-vertex Point3m attribute `name`, created if missing; an attribute of that
//! name but another type is replaced (vcg asserts on adding a name that exists).
CMeshO::PerVertexAttributeHandle<Point3m> pointAttribute(CMeshO& cm, const char* name);

//! The name of the remeshing's new layer: the input's label without its extension, dots made
//! underscores, then "_FCVT" ("bunny.off" -> "bunny_FCVT").
QString outputLayerName(const QString& inputLabel);

//! Writes the valence colours to the live vertices of `layer` (vertex i of `mesh` = i-th live
//! vertex) and returns the counts as a log line.
QString applyValenceColours(const fieldcvt::TriMesh& mesh, MeshModel& layer);

//! Feature lines from a face selection: the edges between a selected and an unselected face
//! (vertex indices of `mesh`, whose face i is the i-th live face, `selected[i]` its flag).
std::vector<std::array<int, 2>> selectionBorder(const fieldcvt::TriMesh& mesh, const std::vector<char>& selected);

//! What the output keeps of the input's per-vertex data.
struct KeptData {
    bool colour = false, quality = false, normals = false;
    bool any() const { return colour || quality || normals; }
};

//! Per-vertex colour / quality / normal of the input carried to the output by closest point and
//! barycentric interpolation (`in`'s vertex i is `inVerts[i]`).
void transferVertexData(const fieldcvt::TriMesh& in, const std::vector<const CVertexO*>& inVerts, const KeptData& keep,
                        CMeshO& out);

//! The live faces' selection flags, in toTriMesh's order (face i = the i-th live face).
std::vector<char> faceSelection(const CMeshO& cm);

//! After "Remesh only selected faces" (vertexOrigin / faceOrigin: output element -> live input
//! element, -1 for a new one; output element i = the i-th of `output`): the kept vertices'
//! colour, quality and normal (as `keep` says) and the kept faces' colour and quality copied from
//! the input exactly, and the selection set to the new faces.
void keepRegionData(const MeshModel& input, const std::vector<int>& vertexOrigin, const std::vector<int>& faceOrigin,
                    const KeptData& keep, MeshModel& output);

}  // namespace fcvt_plugin
