// Keep or bake, over the new faces of a run (all faces without a selection).
#include "texture_output.h"

#include "closest_point.h"

namespace fieldcvt {

namespace {

//! `output` with only its new faces (all without `faceOrigin`), same vertices; `faces` their indices.
TriMesh newFacesOf(const TriMesh& output, const std::vector<int>& faceOrigin, std::vector<int>& faces)
{
    TriMesh part;
    part.vertices = output.vertices;
    for (int f = 0; f < output.faceCount(); ++f)
        if (faceOrigin.empty() || faceOrigin[f] < 0) {
            part.faces.push_back(output.faces[f]);
            faces.push_back(f);
        }
    return part;
}

//! The corner of input face `origin` at corner k of the kept output face f: the kept vertices
//! are the input's bit for bit, and the corners may start elsewhere.
int keptCorner(const TriMesh& input, int origin, const TriMesh& output, int f, int k)
{
    const Vec3& p = output.vertices[output.faces[f][k]];
    for (int j = 0; j < 3; ++j)
        if (input.vertices[input.faces[origin][j]] == p) return j;
    return k;
}

}  // namespace

OutputTexture makeOutputTexture(const TriMesh& input, const MeshTexture& inputTexture,
                                const std::vector<TextureImage>& inputImages, const TriMesh& output,
                                const std::vector<int>& faceOrigin, const OutputTextureParams& params)
{
    OutputTexture result;
    std::vector<int> newFaces;
    const TriMesh part = newFacesOf(output, faceOrigin, newFaces);
    const ClosestPointTree inputTree(input);  // one for the transfer and the bake
    TextureTransferParams transferParams;
    transferParams.threads = params.threads;
    TextureTransferResult kept = transferTexture(input, inputTexture, part, transferParams, &inputTree);
    result.charts = kept.charts;
    result.continuedFaces = kept.continuedFaces;
    result.continuedShare = kept.continuedShare;

    const bool wantBake = params.method == TextureMethod::Bake ||
                          (params.method == TextureMethod::Auto && kept.continuedShare > params.bakeAboveContinuedShare);
    TextureBakeParams bakeParams;
    bakeParams.threads = params.threads;
    bakeParams.maxSize = params.bakeMaxSize;
    if (wantBake) bakeParams.cellSize = bakeCellSize(input, inputTexture, inputImages, part, bakeParams);  // chosen once
    result.tooManyFacesToBake = wantBake && bakeParams.cellSize < kMinBakeCell;
    result.bakeImpossible = wantBake && (inputImages.size() != inputTexture.materials.size() || result.tooManyFacesToBake);
    MeshTexture& texture = result.texture;
    texture.materials = inputTexture.materials;
    texture.libraries = inputTexture.libraries;
    MeshTexture partTexture;
    if (wantBake && !result.bakeImpossible) {
        TextureBakeResult baked = bakeTexture(input, inputTexture, inputImages, part, bakeParams, &inputTree);
        partTexture = std::move(baked.texture);
        result.baked = true;
        result.bakedImage = std::move(baked.image);
        result.cellSize = baked.cellSize;
        // Without kept faces nothing refers to the input's materials any more.
        if (newFaces.size() == output.faces.size()) {
            texture.materials.clear();
            texture.libraries.clear();
        }
        result.bakedMaterial = static_cast<int>(texture.materials.size());
        texture.materials.push_back(partTexture.materials[0]);
        for (int& m : partTexture.faceMaterial) m = result.bakedMaterial;
    } else {
        partTexture = std::move(kept.texture);
    }

    texture.uv.resize(3 * output.faces.size());
    texture.faceMaterial.resize(output.faces.size());
    for (int f = 0; f < output.faceCount(); ++f) {  // the kept faces as they were
        const int origin = faceOrigin.empty() ? -1 : faceOrigin[f];
        if (origin < 0) continue;
        for (int k = 0; k < 3; ++k)
            texture.uv[3 * std::size_t(f) + k] =
                inputTexture.uv[3 * std::size_t(origin) + keptCorner(input, origin, output, f, k)];
        texture.faceMaterial[f] = inputTexture.faceMaterial[origin];
    }
    for (std::size_t i = 0; i < newFaces.size(); ++i) {
        const std::size_t f = static_cast<std::size_t>(newFaces[i]);
        for (int k = 0; k < 3; ++k) texture.uv[3 * f + k] = partTexture.uv[3 * i + k];
        texture.faceMaterial[f] = partTexture.faceMaterial[i];
    }
    return result;
}

}  // namespace fieldcvt
