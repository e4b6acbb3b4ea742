#pragma once
// The output's texture, decided once for the command line and the MeshLab filter:
// the input's atlas kept (texture_transfer.h) or a new image baked (texture_bake.h), chosen per
// mesh; after a selection-only run the kept faces keep their own coordinates exactly.
#include "mesh.h"
#include "mesh_texture.h"
#include "texture_bake.h"
#include "texture_image.h"
#include "texture_transfer.h"

#include <vector>

namespace fieldcvt {

enum class TextureMethod {
    Auto,  //!< bake when keeping would put more than `bakeAboveContinuedShare` of the new faces across a seam
    Keep,  //!< the input's atlas and images
    Bake,  //!< a new image
};

struct OutputTextureParams {
    TextureMethod method = TextureMethod::Auto;
    double bakeAboveContinuedShare = kBakeAboveContinuedShare;  //!< 0.1
    int threads = 0;         //!< OpenMP threads; 0 = OpenMP's default. The result does not depend on it.
    int bakeMaxSize = 4096;  //!< the baked image's largest side (TextureBakeParams::maxSize)
};

struct OutputTexture {
    MeshTexture texture;  //!< 3 coordinates per output face; the input's materials, then the baked one if any
    bool baked = false;
    TextureImage bakedImage;  //!< when baked: the image of material `bakedMaterial`, whose file the caller names
    int bakedMaterial = -1;
    int cellSize = 0;
    int charts = 0;               //!< the input atlas's charts
    int continuedFaces = 0;       //!< new faces across a seam when the atlas is kept
    double continuedShare = 0.0;  //!< continuedFaces / new faces
    //! A bake was wanted but `inputImages` was empty, or the output has too many faces for cells
    //! of kMinBakeCell texels within `bakeMaxSize`: the atlas kept.
    bool bakeImpossible = false;
    bool tooManyFacesToBake = false;  //!< the second reason
};

//! The texture of `output`, remeshed from `input` (`inputTexture` fits it, textureProblem is
//! empty). `inputImages`: one per material, or empty when they cannot be read (then the atlas is
//! kept). `faceOrigin` (a selection-only run; empty otherwise): output face -> input face, -1
//! for a new face; kept faces take the input's coordinates and material as they were.
OutputTexture makeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture,
                                const std::vector<TextureImage>& inputImages, const TriMesh& output,
                                const std::vector<int>& faceOrigin, const OutputTextureParams& params);

}  // namespace fieldcvt
