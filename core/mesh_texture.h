#pragma once
// Per-corner texture coordinates and materials next to a TriMesh: what the OBJ and PLY
// readers keep, the texture transfer (texture_transfer.h) computes and the writers write.
#include "mesh.h"

#include <string>
#include <vector>

namespace fieldcvt {

using Vec2 = Eigen::Vector2d;

//! One material (OBJ `usemtl`) or texture (PLY `TextureFile`) the faces refer to.
struct TextureMaterial {
    std::string name;   //!< the OBJ material name; empty for PLY
    std::string image;  //!< the texture image as the file names it (PLY; OBJ when its .mtl was read), may be empty
};

//! Texture coordinates per face corner; empty `uv` = the mesh has none.
struct MeshTexture {
    std::vector<Vec2> uv;                    //!< 3 per face: corner k of face f at 3 f + k
    std::vector<int> faceMaterial;           //!< per face, an index into `materials`
    std::vector<TextureMaterial> materials;  //!< at least one when `uv` is not empty
    std::vector<std::string> libraries;      //!< OBJ `mtllib` file names, as written (relative to the mesh's folder)

    bool empty() const { return uv.empty(); }
};

//! Empty when `texture` fits `mesh` (3 finite coordinates per face, a material in range per
//! face), else what is wrong, in one line (the caller drops the texture with a warning).
std::string textureProblem(const TriMesh& mesh, const MeshTexture& texture);

}  // namespace fieldcvt
