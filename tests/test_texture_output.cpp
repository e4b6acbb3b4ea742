// The output's texture decided once for the CLI and the filter (core/texture_output.h): auto's
// choice, the kept faces of a selection-only run, the fallback without images.
#include "test_meshes.h"
#include "texture_output.h"

#include <gtest/gtest.h>

namespace fieldcvt {
namespace {

using namespace testmesh;

//! One chart per face (every edge a seam, as sub.obj): keeping it puts most faces across a seam.
MeshTexture chartPerFace(const TriMesh& m)
{
    MeshTexture t;
    t.materials = {{"in", "in.png"}};
    for (int f = 0; f < m.faceCount(); ++f) {
        const Vec2 origin(0.01 * (f % 50), 0.01 * (f / 50));
        t.uv.insert(t.uv.end(), {origin, origin + Vec2(0.008, 0), origin + Vec2(0, 0.008)});
        t.faceMaterial.push_back(0);
    }
    return t;
}

TextureImage grey(int size)
{
    TextureImage image;
    image.width = image.height = size;
    image.rgb.assign(3 * size * size, 90);
    return image;
}

TEST(TextureOutput, AutoBakesWhenKeepingWouldPutFacesAcrossSeams)
{
    const TriMesh input = planeGrid(8), output = planeGrid(5);
    const OutputTexture made = makeOutputTexture(input, chartPerFace(input), {grey(64)}, output, {}, OutputTextureParams{});
    EXPECT_GT(made.continuedShare, kBakeAboveContinuedShare);
    ASSERT_TRUE(made.baked);
    // Nothing refers to the input's material any more: the baked one alone.
    ASSERT_EQ(made.texture.materials.size(), 1u);
    EXPECT_EQ(made.bakedMaterial, 0);
    EXPECT_EQ(made.texture.uv.size(), 3 * output.faces.size());
    EXPECT_FALSE(made.bakedImage.empty());
}

TEST(TextureOutput, KeepAndNoImagesKeepTheAtlas)
{
    const TriMesh input = planeGrid(8), output = planeGrid(5);
    OutputTextureParams keep;
    keep.method = TextureMethod::Keep;
    const OutputTexture kept = makeOutputTexture(input, chartPerFace(input), {grey(64)}, output, {}, keep);
    EXPECT_FALSE(kept.baked);
    EXPECT_FALSE(kept.bakeImpossible);
    const OutputTexture noImages = makeOutputTexture(input, chartPerFace(input), {}, output, {}, OutputTextureParams{});
    EXPECT_FALSE(noImages.baked);
    EXPECT_TRUE(noImages.bakeImpossible);
    EXPECT_EQ(noImages.texture.materials.size(), 1u);
    EXPECT_EQ(noImages.texture.uv, kept.texture.uv);
}

TEST(TextureOutput, TooManyFacesForTheImageKeepTheAtlas)
{
    // 50 output faces, at most 16 texels a side: cells of 8 texels do not fit.
    const TriMesh input = planeGrid(8), output = planeGrid(5);
    OutputTextureParams params;
    params.method = TextureMethod::Bake;
    params.bakeMaxSize = 16;
    const OutputTexture made = makeOutputTexture(input, chartPerFace(input), {grey(64)}, output, {}, params);
    EXPECT_FALSE(made.baked);
    EXPECT_TRUE(made.bakeImpossible);
    EXPECT_TRUE(made.tooManyFacesToBake);
    EXPECT_EQ(made.texture.uv.size(), 3 * output.faces.size());
    params.bakeMaxSize = 4096;
    EXPECT_TRUE(makeOutputTexture(input, chartPerFace(input), {grey(64)}, output, {}, params).baked);
}

TEST(TextureOutput, KeptFacesOfASelectionKeepTheirCoordinatesAndTheNewOnesAreBaked)
{
    // The output: the input's faces, the first half kept (origin = the face), the rest "new".
    const TriMesh input = planeGrid(8);
    const MeshTexture texture = chartPerFace(input);
    std::vector<int> faceOrigin(input.faces.size(), -1);
    for (int f = 0; f < input.faceCount() / 2; ++f) faceOrigin[f] = f;
    const OutputTexture made = makeOutputTexture(input, texture, {grey(64)}, input, faceOrigin, OutputTextureParams{});
    ASSERT_TRUE(made.baked);
    ASSERT_EQ(made.texture.materials.size(), 2u);  // the input's, then the baked one
    EXPECT_EQ(made.bakedMaterial, 1);
    for (int f = 0; f < input.faceCount(); ++f) {
        if (faceOrigin[f] >= 0) {
            EXPECT_EQ(made.texture.faceMaterial[f], 0);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(made.texture.uv[3 * f + k], texture.uv[3 * f + k]);
        } else {
            EXPECT_EQ(made.texture.faceMaterial[f], 1);
        }
    }
}

}  // namespace
}  // namespace fieldcvt
