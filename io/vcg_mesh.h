#pragma once
// The small double-precision vcglib mesh that vcglib's STL importer and OFF/STL exporters work
// on; only the I/O translation units see vcglib.
#include <vcg/complex/complex.h>

namespace fieldcvt::io_detail {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes : vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::BitFlags> {};
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {};

}  // namespace fieldcvt::io_detail
