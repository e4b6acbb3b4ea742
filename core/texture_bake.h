#pragma once
// A new texture for the remeshed surface: where the input's atlas has charts as small
// as the output's faces (e.g. one chart per triangle), keeping it would map most output faces
// across a seam. Instead each output face gets its own triangle in a new atlas, and each texel
// the input's colour at its closest point on the input.
#include "mesh.h"
#include "mesh_texture.h"
#include "texture_image.h"

#include <vector>

namespace fieldcvt {

class ClosestPointTree;

//! Above this share of output faces across a seam when the input's atlas is kept
//! (TextureTransferResult::continuedShare), a new texture is baked by default: the input's charts
//! are small against the output's faces (docs/tuning.md, "kBakeAboveContinuedShare").
constexpr double kBakeAboveContinuedShare = 0.1;

//! The smallest cell worth baking into, in texels: its triangles' legs are 3 texels long
//! inside their margins.
constexpr int kMinBakeCell = 8;

struct TextureBakeParams {
    //! Side of the square cell that holds two output faces, in texels; 0 = chosen so that the
    //! new image has about eight times as many texels on the surface as the input's images (the
    //! input's detail kept through two resamplings and the margins), within [16, 64] and `maxSize`.
    int cellSize = 0;
    //! The new image's largest side, in texels (default 4096; the cell size shrinks to fit, not
    //! below kMinBakeCell: with more faces than that allows, about 520 000, no bake is made).
    int maxSize = 4096;
    //! OpenMP threads; 0 = OpenMP's default. The result does not depend on it.
    int threads = 0;
};

struct TextureBakeResult {
    MeshTexture
        texture;  //!< for the output: 3 coordinates per face into `image`, one material (its image unnamed: the caller names the file)
    TextureImage image;
    int cellSize = 0;  //!< the cell side used, in texels
};

//! Output face f lies in cell f / 2 (cells row by row), the lower-left half of it for even f,
//! the upper-right half for odd f, 1.5 texels inside the cell and away from the other half, so
//! that bilinear sampling never mixes two faces. Every texel of a cell is filled (from the face
//! of its half, at the texel centre's closest point in that face), the margins included.
//! `inputImages` has one image per material of `inputTexture` (an empty one reads mid-grey);
//! `inputTexture` must fit `input` (textureProblem is empty).
//! `inputTree`: closest-point queries on `input` when the caller has them (else built here).
TextureBakeResult bakeTexture(const TriMesh& input, const MeshTexture& inputTexture, const std::vector<TextureImage>& inputImages,
                              const TriMesh& output, const TextureBakeParams& params = {},
                              const ClosestPointTree* inputTree = nullptr);

//! The cell side bakeTexture chooses for these meshes and parameters (cellSize 0).
int bakeCellSize(const TriMesh& input, const MeshTexture& inputTexture, const std::vector<TextureImage>& inputImages,
                 const TriMesh& output, const TextureBakeParams& params);

}  // namespace fieldcvt
