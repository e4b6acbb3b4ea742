// The textured renders behind `fcvt texture-compare` (core/texture_render.h, issue 36 item 3).
#include "test_meshes.h"
#include "texture_render.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fieldcvt {
namespace {

using namespace testmesh;

TextureImage checkerboard(int size, int squares)
{
    TextureImage image;
    image.width = image.height = size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool dark = ((x * squares / size) + (y * squares / size)) % 2;
            for (int k = 0; k < 3; ++k) image.rgb.push_back(dark ? 30 : 220);
        }
    return image;
}

MeshTexture xyTexture(const TriMesh& m)
{
    MeshTexture t;
    t.materials = {{"", ""}};
    for (const Face& f : m.faces) {
        for (int v : f) t.uv.emplace_back(m.vertices[v].x(), m.vertices[v].y());
        t.faceMaterial.push_back(0);
    }
    return t;
}

//! Looking down -z at the unit square, which fills `size` pixels exactly.
RenderCamera squareCamera(int size)
{
    RenderCamera c;
    c.centre = Vec3(0.5, 0.5, 0);
    c.pixelSize = 1.0 / size;
    c.size = size;
    return c;
}

TEST(TextureRender, SquareFillsThePictureWithItsTexture)
{
    const TriMesh square = planeGrid(3);
    const TextureImage image = checkerboard(64, 4);
    const TextureRender r = renderTextured(square, xyTexture(square), {image}, squareCamera(64));
    long long covered = 0;
    double worst = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * 64 + x;
            covered += r.covered[i];
            // Pixel centres fall on texel centres: the picture is the image itself.
            worst = std::max(worst, double((r.colour[i] - image.pixel(x, y).cast<float>()).cwiseAbs().maxCoeff()));
        }
    EXPECT_EQ(covered, 64 * 64);
    EXPECT_LT(worst, 1e-3);
}

TEST(TextureRender, TheNearestFaceIsSeen)
{
    TriMesh two = planeGrid(1);
    TriMesh back = planeGrid(1);
    for (Vec3& p : back.vertices) p.z() = -1;  // farther along the camera's forward (-z) axis
    MeshTexture t = xyTexture(two);
    const int offset = two.vertexCount();
    for (const Vec3& p : back.vertices) two.vertices.push_back(p);
    for (Face f : back.faces) {
        for (int& v : f) v += offset;
        two.faces.push_back(f);
        for (int k = 0; k < 3; ++k) t.uv.emplace_back(0.0, 0.0);
        t.faceMaterial.push_back(1);
    }
    t.materials.push_back({"", ""});
    TextureImage white = checkerboard(4, 1), black;
    black.width = black.height = 1;
    black.rgb = {0, 0, 0};
    // Drawn after the front square, the back one must not cover it.
    const TextureRender r = renderTextured(two, t, {white, black}, squareCamera(16));
    for (std::size_t i = 0; i < r.colour.size(); ++i) ASSERT_GT(r.colour[i].minCoeff(), 100.0f);
}

TEST(TextureRender, IdenticalRendersDoNotDifferAndAHalfPixelShiftDoes)
{
    const TriMesh sphere = icosphere(3);
    MeshTexture t = xyTexture(sphere);
    const std::vector<TextureImage> images = {checkerboard(128, 8)};
    const std::vector<RenderCamera> cameras = camerasAround(sphere, 6, 96);
    ASSERT_EQ(cameras.size(), 6u);
    for (const RenderCamera& c : cameras) {
        const TextureRender a = renderTextured(sphere, t, images, c);
        const RenderDifference same = compareRenders(a, renderTextured(sphere, t, images, c));
        EXPECT_EQ(same.meanAbsolute, 0.0);
        EXPECT_GT(same.pixels, 96 * 96 / 5);  // the unit sphere in its bounding box's sphere: 1 / (3 pi) of the picture
        RenderCamera shifted = c;
        shifted.shift = {0.5, 0.0};
        EXPECT_GT(compareRenders(a, renderTextured(sphere, t, images, shifted)).meanAbsolute, 0.5);
    }
}

TEST(TextureRender, TheImageRepeatsOutsideTheUnitSquareAndFarCoordinatesStayInRange)
{
    const TextureImage image = checkerboard(16, 4);
    EXPECT_EQ(image.sample(5.3, -2.6), image.sample(0.3, 0.4));
    // Coordinates continued across a seam can be far out; NaN reads black.
    for (const double u : {1e300, -1e300, 1e18, -7e15}) {
        const Eigen::Vector3d c = image.sample(u, 0.5);
        EXPECT_TRUE(c.allFinite());
        EXPECT_GE(c.minCoeff(), 0.0);
        EXPECT_LE(c.maxCoeff(), 255.0);
    }
    EXPECT_EQ(image.sample(std::nan(""), 0.5), Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace fieldcvt
