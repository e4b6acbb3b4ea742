#pragma once
// CMeshO, MeshModel and MeshDocument from whichever MeshLab the plugin is built against
// (FCVT_MESHLAB_API, set by filter_fcvt/CMakeLists.txt): the types the MeshLab-neutral part of
// the plugin works on are the same in both, only their headers moved.
#if FCVT_MESHLAB_API == 2020
#include <common/meshmodel.h>
#include <common/ml_mesh_type.h>
#elif FCVT_MESHLAB_API == 2022
#include <common/ml_document/cmesh.h>
#include <common/ml_document/mesh_document.h>
#else
#error "FCVT_MESHLAB_API must be 2020 or 2022"
#endif

namespace fcvt_plugin {

//! Removes a layer from the document (2020.09 takes the model, 2022.02 its id).
inline void removeLayer(MeshDocument& md, MeshModel* layer)
{
#if FCVT_MESHLAB_API == 2020
    md.delMesh(layer);
#else
    md.delMesh(static_cast<unsigned int>(layer->id()));
#endif
}

//! Bounding box and normals of a layer after its mesh changed (2022.02 lower-cased the name).
inline void updateBoxAndNormals(MeshModel& layer)
{
#if FCVT_MESHLAB_API == 2020
    layer.UpdateBoxAndNormals();
#else
    layer.updateBoxAndNormals();
#endif
}

}  // namespace fcvt_plugin
