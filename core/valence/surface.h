#pragma once
// What the valence optimisation (valence.h) works on: the input surface the optimised mesh lives
// on and what each vertex of that mesh may do. The types its parts (valence_mesh.h and above) and
// its callers share; the round loop itself is valence.cpp.
#include "boundary.h"
#include "closest_point.h"
#include "field_types.h"
#include "mesh.h"

#include <vector>

namespace fieldcvt {

//! What a vertex of the mesh being optimised may do.
enum class VertexRole : char {
    Free,      //!< interior vertex: moves tangentially, projected on the input surface
    Boundary,  //!< on the input's open border: stays where it is (see optimizeValence); target valence 4
    Feature,   //!< on a sharp feature line: moves only along it
    Corner,    //!< fixed (feature corner, end of a feature curve)
};

//! The input surface the optimised mesh lives on (all at the working scale).
struct ValenceSurface {
    const TriMesh& input;                   //!< the input surface
    const ClosestPointTree& tree;           //!< closest points on `input`
    std::vector<Segment> features;          //!< sharp feature lines (Feature vertices stay on them)
    const DirectionField* field = nullptr;  //!< 6-RoSy field on `input` for the final relaxation (null: none)
    //! The input's open border. A Free vertex that the mesh has on its border (a sample whose cell
    //! reached the border during the FCVT iterations) is put on it before it becomes Boundary;
    //! empty: left where it is.
    std::vector<Segment> border;
};

}  // namespace fieldcvt
