// The baked texture (core/texture_bake.h, issue 36): each output face in its own triangle of the
// new atlas, apart from the others, each texel the input's colour at its closest point.
#include "test_meshes.h"
#include "texture_bake.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <map>
#include <set>
#include <cmath>

namespace fieldcvt {
namespace {

using namespace testmesh;

//! uv = 0.1 + 0.8 (x, y) on the unit plane grid: the plane seen from above, away from the
//! image's borders (where sampling would wrap to the other side).
Vec2 planeToUv(const Vec3& p) { return Vec2(0.1 + 0.8 * p.x(), 0.1 + 0.8 * p.y()); }

MeshTexture planeUv(const TriMesh& m)
{
    MeshTexture t;
    t.materials = {{"", ""}};
    for (const Face& f : m.faces) {
        for (int v : f) t.uv.push_back(planeToUv(m.vertices[v]));
        t.faceMaterial.push_back(0);
    }
    return t;
}

//! A smooth picture: red grows to the right, green upwards, blue with both.
TextureImage gradient(int size)
{
    TextureImage image;
    image.width = image.height = size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = 1.0 - (y + 0.5) / size;
            image.rgb.push_back(static_cast<std::uint8_t>(std::lround(40 + 170 * u)));
            image.rgb.push_back(static_cast<std::uint8_t>(std::lround(30 + 200 * v)));
            image.rgb.push_back(static_cast<std::uint8_t>(std::lround(20 + 100 * (u + v))));
        }
    return image;
}

//! Another triangulation of the same square, its inner vertices moved in the plane.
TriMesh otherPlane()
{
    TriMesh m = planeGrid(9);
    for (Vec3& p : m.vertices)
        if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1)
            p += Vec3(0.02 * std::sin(13 * p.y()), 0.02 * std::cos(7 * p.x()), 0);
    return m;
}

TEST(TextureBake, BakedPlaneShowsTheInputsPictureAtEveryPointOfEveryFace)
{
    const TriMesh input = planeGrid(6), output = otherPlane();
    const TextureImage picture = gradient(256);
    const TextureBakeResult baked = bakeTexture(input, planeUv(input), {picture}, output);
    ASSERT_EQ(baked.texture.uv.size(), 3 * output.faces.size());
    ASSERT_FALSE(baked.image.empty());
    double worst = 0;
    for (int f = 0; f < output.faceCount(); ++f)
        for (const Vec3& w : {Vec3(Vec3(1, 1, 1) / 3), Vec3(0.6, 0.2, 0.2), Vec3(0.1, 0.1, 0.8), Vec3(0.05, 0.9, 0.05)}) {
            Vec3 p = Vec3::Zero();
            Vec2 uv = Vec2::Zero();
            for (int k = 0; k < 3; ++k) {
                p += w[k] * output.vertices[output.faces[f][k]];
                uv += w[k] * baked.texture.uv[3 * f + k];
            }
            const double e =
                (baked.image.sample(uv.x(), uv.y()) - picture.sample(planeToUv(p).x(), planeToUv(p).y())).cwiseAbs().maxCoeff();
            worst = std::max(worst, e);
        }
    // The picture changes by under 1 per texel: only rounding and the texel grid's offset remain.
    EXPECT_LT(worst, 2.5);
}

TEST(TextureBake, EachFaceHasItsOwnTriangleWithAMarginToTheOthers)
{
    const TriMesh input = planeGrid(6), output = otherPlane();
    TextureBakeParams params;
    params.cellSize = 12;
    const TextureBakeResult baked = bakeTexture(input, planeUv(input), {gradient(64)}, output, params);
    EXPECT_EQ(baked.cellSize, 12);
    std::set<std::array<int, 3>> taken;  // (cell column, cell row, half)
    for (int f = 0; f < output.faceCount(); ++f) {
        std::array<Vec2, 3> texel;
        Vec2 low = Vec2::Constant(1e300);
        for (int k = 0; k < 3; ++k) {
            const Vec2& uv = baked.texture.uv[3 * f + k];
            texel[k] = Vec2(uv.x() * baked.image.width, (1.0 - uv.y()) * baked.image.height);
            low = low.cwiseMin(texel[k]);
        }
        const int column = static_cast<int>(low.x() / 12), row = static_cast<int>(low.y() / 12);
        const Vec2 origin(12.0 * column, 12.0 * row);
        bool lower = true;
        for (int k = 0; k < 3; ++k) {
            const Vec2 local = texel[k] - origin;
            // 1.5 texels inside the cell, and 1.5 texels from the diagonal that parts its two faces.
            EXPECT_GE(local.minCoeff(), 1.5 - 1e-9);
            EXPECT_LE(local.maxCoeff(), 12 - 1.5 + 1e-9);
            const double toDiagonal = (local.x() + local.y() - 12.0) / std::sqrt(2.0);
            EXPECT_GE(std::abs(toDiagonal), 1.5 - 1e-9);
            lower = lower && toDiagonal < 0;
        }
        EXPECT_TRUE(taken.insert({column, row, lower ? 0 : 1}).second) << "two faces in one half of a cell";
    }
}

TEST(TextureBake, NeighboursInTheImageAreNeighboursOnTheSurface)
{
    // Viewers average neighbouring texels (mipmaps): the two faces of a cell, and the faces of
    // neighbouring cells, should lie close together on the surface.
    // The output's faces in a scrambled order (a remesher's numbering need not follow the surface).
    const TriMesh input = planeGrid(6);
    TriMesh output = planeGrid(30);
    std::mt19937 random(7);
    std::shuffle(output.faces.begin(), output.faces.end(), random);
    TextureBakeParams params;
    params.cellSize = 8;
    const TextureBakeResult baked = bakeTexture(input, planeUv(input), {gradient(64)}, output, params);
    std::map<std::pair<int, int>, std::vector<Vec3>> cells;  // cell -> its faces' centroids
    for (int f = 0; f < output.faceCount(); ++f) {
        const Vec2& uv = baked.texture.uv[3 * f];
        const int column = static_cast<int>(uv.x() * baked.image.width / 8),
                  row = static_cast<int>((1.0 - uv.y()) * baked.image.height / 8);
        const Face& face = output.faces[f];
        cells[{column, row}].push_back((output.vertices[face[0]] + output.vertices[face[1]] + output.vertices[face[2]]) / 3.0);
    }
    double total = 0;
    int pairs = 0;
    for (const auto& [at, centroids] : cells) {
        const auto right = cells.find({at.first + 1, at.second});
        if (right == cells.end()) continue;
        total += (centroids[0] - right->second[0]).norm();
        ++pairs;
    }
    ASSERT_GT(pairs, 100);
    // A face of this grid is 1/30 across; faces placed at random would be about 0.5 apart.
    EXPECT_LT(total / pairs, 0.15);
}

TEST(TextureBake, TheSameImageOnOneAndTwoThreads)
{
    const TriMesh input = icosphere(3), output = icosphere(2);
    MeshTexture t;
    t.materials = {{"", ""}};
    for (const Face& f : input.faces) {
        for (int v : f) t.uv.emplace_back(0.5 + 0.4 * input.vertices[v].x(), 0.5 + 0.4 * input.vertices[v].y());
        t.faceMaterial.push_back(0);
    }
    TextureBakeParams one, two;
    one.threads = 1;
    two.threads = 2;
    const TextureBakeResult a = bakeTexture(input, t, {gradient(128)}, output, one);
    const TextureBakeResult b = bakeTexture(input, t, {gradient(128)}, output, two);
    EXPECT_EQ(a.image.rgb, b.image.rgb);
    EXPECT_EQ(a.texture.uv, b.texture.uv);
}

TEST(TextureBake, CellsShrinkToKeepTheImageWithinItsLargestSide)
{
    const TriMesh input = planeGrid(6), output = otherPlane();
    TextureBakeParams params;
    params.cellSize = 64;
    params.maxSize = 256;
    const TextureBakeResult baked = bakeTexture(input, planeUv(input), {gradient(64)}, output, params);
    EXPECT_LE(std::max(baked.image.width, baked.image.height), 256);
    EXPECT_LT(baked.cellSize, 64);
    // Without a cell size: about eight times the input's texels per face, never below 16.
    const int chosen = bakeCellSize(input, planeUv(input), {gradient(64)}, output, TextureBakeParams{});
    EXPECT_GE(chosen, 16);
    EXPECT_LE(chosen, 64);
}

TEST(TextureBake, AMaterialWithoutAnImageBakesMidGrey)
{
    const TriMesh input = planeGrid(4), output = otherPlane();
    const TextureBakeResult baked = bakeTexture(input, planeUv(input), {TextureImage{}}, output);
    for (std::uint8_t c : baked.image.rgb) ASSERT_EQ(c, 128);
}

}  // namespace
}  // namespace fieldcvt
