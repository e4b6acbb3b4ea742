#pragma once
// Texture coordinates carried from the input onto the remeshed surface, keeping the input's
// atlas: each output face is mapped whole into one chart of the input's atlas, so no
// face stretches across a seam.
#include "mesh.h"
#include "mesh_texture.h"

#include <vector>

namespace fieldcvt {

class ClosestPointTree;

struct TextureTransferParams {
    //! Two corners of a shared edge have "the same" coordinates when they differ by at most this
    //! in each of u and v (default 0: equal, as two `f v/vt` corners naming one `vt` are).
    double uvTolerance = 0.0;
    //! OpenMP threads for the closest-point queries; 0 = OpenMP's default. The result does not depend on it.
    int threads = 0;
};

struct TextureTransferResult {
    MeshTexture texture;     //!< for the output mesh: 3 coordinates per face, the input's materials
    int charts = 0;          //!< charts of the input's atlas
    int continuedFaces = 0;  //!< output faces with a corner continued across a seam (its closest point in another chart)
    //! continuedFaces / the output's face count (0 without faces).
    double continuedShare = 0.0;
};

//! The input's charts: connected components of faces through edges whose two corners have the
//! same coordinates on both faces, and whose faces have the same material. Per face, its chart
//! (0 .. count - 1, numbered in the order of their first face); `count` receives the number.
std::vector<int> textureCharts(const TriMesh& mesh, const MeshTexture& texture, double uvTolerance, int* count = nullptr);

//! Per-corner coordinates for `output` (in `input`'s frame). Each output face takes the chart
//! of its centroid's closest input face f*; a corner whose closest point lies in that chart takes
//! the coordinates interpolated there, unless they jump from f*'s affine map by more than the
//! face's size there (a seam inside the chart); any other corner is continued with f*'s affine
//! map (its barycentric coordinates in f*'s plane, unbounded, applied to f*'s coordinates). The
//! face's material is f*'s. `inputTexture` must fit `input` (textureProblem is empty).
//! `inputTree`: closest-point queries on `input` when the caller has them (else built here).
TextureTransferResult transferTexture(const TriMesh& input, const MeshTexture& inputTexture, const TriMesh& output,
                                      const TextureTransferParams& params = {}, const ClosestPointTree* inputTree = nullptr);

}  // namespace fieldcvt
