#pragma once
// The small double-precision vcglib mesh that vcglib's importers and exporters work on; only
// the I/O translation units see vcglib.
#include <vcg/complex/complex.h>

namespace fieldcvt::io_detail {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes : vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::BitFlags> {};
// Face flags carry vcglib's "faux edge" marks, from which we count the polygons it triangulated.
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {};

}  // namespace fieldcvt::io_detail
