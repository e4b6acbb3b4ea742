#pragma once
// The input layer's texture carried to the remeshed layer (issue 36): MeshLab's wedge texture
// coordinates (per face corner, with the texture index) and the layer's textures.
#include <QString>

#include "meshlab_types.h"
#include "mesh.h"
#include "mesh_texture.h"

#include <vector>

namespace fcvt_plugin {

//! The layer's live faces with their wedge texture coordinates (face i = the i-th live face, its
//! material the first corner's texture index, materials named after cm.textures); an empty
//! texture when the layer has none or they do not fit (NaN, an index out of range).
fieldcvt::MeshTexture layerTexture(const MeshModel& layer, const fieldcvt::TriMesh& layerMesh, QString* problem);

//! Gives `output` (whose i-th face is `outputMesh`'s face i) wedge texture coordinates from
//! `input`'s and `input`'s textures, as the CLI does: the input's atlas kept, or a new image
//! baked when keeping would put more than fieldcvt::kBakeAboveContinuedShare of the faces across
//! a seam, named "<layer>_texture.png" (held in the layer on MeshLab 2022.02 and later; on
//! 2020.09, whose layers hold names only, a file beside the input's). Returns the log line
//! (empty when the input has no texture coordinates).
//! After a selection-only run (`faceOrigin`: output face -> live input face, -1 for a new one)
//! the kept faces keep their coordinates; without one `faceOrigin` is empty.
QString transferLayerTexture(const MeshModel& input, const fieldcvt::TriMesh& outputMesh, const std::vector<int>& faceOrigin,
                             int threads, MeshModel& output);

}  // namespace fcvt_plugin
