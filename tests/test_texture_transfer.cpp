// Texture transfer (core/texture_transfer.h, issue 36): charts, the input's atlas kept on a new
// triangulation, faces across a seam mapped whole into one chart, thread count invariance.
#include "test_meshes.h"
#include "texture_transfer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace fieldcvt {
namespace {

using namespace testmesh;

//! The linear map of the plane tests: uv = A (x, y) + b.
Vec2 linearUv(const Vec3& p) { return {0.3 * p.x() + 0.1 * p.y() + 0.2, -0.05 * p.x() + 0.7 * p.y() + 0.1}; }

//! planeGrid's texture by linearUv, plus `rightOffset` on the faces right of x = 0.5 (their own chart then).
MeshTexture planeTexture(const TriMesh& m, const Vec2& rightOffset)
{
    MeshTexture t;
    t.materials = {{"", ""}};
    for (const Face& f : m.faces) {
        const bool right = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]).x() / 3 > 0.5;
        for (int v : f) t.uv.push_back(linearUv(m.vertices[v]) + (right ? rightOffset : Vec2::Zero()));
        t.faceMaterial.push_back(0);
    }
    return t;
}

//! A grid of another resolution whose inner vertices are moved in the plane (no vertex on x = 0.5).
TriMesh jiggledPlane()
{
    TriMesh m = planeGrid(7);
    for (Vec3& p : m.vertices)
        if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1)
            p += Vec3(0.02 * std::sin(17 * p.y()), 0.02 * std::cos(11 * p.x()), 0);
    return m;
}

TEST(TextureTransfer, PlaneWithLinearMapIsReproduced)
{
    const TriMesh input = planeGrid(10), output = jiggledPlane();
    const TextureTransferResult r = transferTexture(input, planeTexture(input, Vec2::Zero()), output);
    EXPECT_EQ(r.charts, 1);
    EXPECT_EQ(r.continuedFaces, 0);
    ASSERT_EQ(r.texture.uv.size(), 3 * output.faces.size());
    for (int f = 0; f < output.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            EXPECT_LT((r.texture.uv[3 * f + k] - linearUv(output.vertices[output.faces[f][k]])).norm(), 1e-12);
}

TEST(TextureTransfer, PlaneSeamFacesTakeOneChartsMap)
{
    const TriMesh input = planeGrid(10), output = jiggledPlane();
    const TextureTransferResult r = transferTexture(input, planeTexture(input, Vec2(5, 0)), output);
    EXPECT_EQ(r.charts, 2);
    EXPECT_GT(r.continuedFaces, 0);
    for (int f = 0; f < output.faceCount(); ++f) {
        // Each face has one chart's map, offset 0 or (5, 0), at all three corners (continued ones too).
        const Vec2 offset = r.texture.uv[3 * f] - linearUv(output.vertices[output.faces[f][0]]);
        EXPECT_TRUE(offset.norm() < 1e-12 || (offset - Vec2(5, 0)).norm() < 1e-12) << "face " << f;
        for (int k = 1; k < 3; ++k)
            EXPECT_LT((r.texture.uv[3 * f + k] - linearUv(output.vertices[output.faces[f][k]]) - offset).norm(), 1e-12);
    }
}

//! The cube [-1, 1]^3, n x n squares per side (vertices shared along its edges), with a 3 x 2 atlas:
//! side c = 2 axis + (sign > 0) in tile (c % 3, c / 3), each seen counter-clockwise from outside.
struct TexturedCube {
    TriMesh mesh;
    MeshTexture texture;
};

//! The coordinates of point p of cube side c (its tile, with a margin).
Vec2 cubeUv(int c, const Vec3& p)
{
    const int axis = c / 2;
    const double sign = c % 2 ? 1.0 : -1.0;
    const double u = sign * p[(axis + 1) % 3], v = p[(axis + 2) % 3];  // mirrored on the negative sides
    return {(c % 3) / 3.0 + 0.02 + 0.145 * (u + 1), (c / 3) / 2.0 + 0.02 + 0.23 * (v + 1)};
}
constexpr double kCubeUvPerArea = 0.145 * 0.23;

TexturedCube texturedCube(int n)
{
    TexturedCube cube;
    std::map<std::tuple<int, int, int>, int> index;
    auto vertex = [&](int i, int j, int k) {
        const auto key = std::make_tuple(i, j, k);
        if (const auto it = index.find(key); it != index.end()) return it->second;
        cube.mesh.vertices.emplace_back(2.0 * i / n - 1, 2.0 * j / n - 1, 2.0 * k / n - 1);
        return index[key] = cube.mesh.vertexCount() - 1;
    };
    cube.texture.materials = {{"", ""}};
    for (int c = 0; c < 6; ++c) {
        const int axis = c / 2;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                int corner[4];
                const int ua[4] = {a, a + 1, a + 1, a}, vb[4] = {b, b, b + 1, b + 1};
                for (int q = 0; q < 4; ++q) {
                    int ijk[3];
                    ijk[axis] = c % 2 ? n : 0;
                    ijk[(axis + 1) % 3] = c % 2 ? ua[q] : n - ua[q];  // mirrored u on the negative sides
                    ijk[(axis + 2) % 3] = vb[q];
                    corner[q] = vertex(ijk[0], ijk[1], ijk[2]);
                }
                for (const Face& f : {Face{corner[0], corner[1], corner[2]}, Face{corner[0], corner[2], corner[3]}}) {
                    cube.mesh.faces.push_back(f);
                    for (int v : f) cube.texture.uv.push_back(cubeUv(c, cube.mesh.vertices[v]));
                    cube.texture.faceMaterial.push_back(0);
                }
            }
    }
    return cube;
}

//! An icosphere pushed radially onto the cube: its faces bend across the cube's edges.
TriMesh sphereOnCube()
{
    TriMesh m = icosphere(3);
    for (Vec3& p : m.vertices) p /= p.cwiseAbs().maxCoeff();
    return m;
}

double signedUvArea(const Vec2& a, const Vec2& b, const Vec2& c)
{
    return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

TEST(TextureTransfer, CubeAtlasSeamFacesStayInOneTile)
{
    const TexturedCube cube = texturedCube(6);
    EXPECT_EQ(cube.mesh.vertexCount(), 6 * 36 + 2);
    const TriMesh output = sphereOnCube();
    const TextureTransferResult r = transferTexture(cube.mesh, cube.texture, output);
    EXPECT_EQ(r.charts, 6);
    EXPECT_GT(r.continuedFaces, 0);
    EXPECT_LT(r.continuedShare, 0.5);
    int seamFaces = 0;
    for (int f = 0; f < output.faceCount(); ++f) {
        const Vec2* uv = &r.texture.uv[3 * f];
        const Vec2 centre = (uv[0] + uv[1] + uv[2]) / 3;
        const double tileU = std::floor(centre.x() * 3) / 3, tileV = std::floor(centre.y() * 2) / 2;
        for (int k = 0; k < 3; ++k) {  // every corner within the centre's tile (a continued one just past its margin)
            EXPECT_GT(uv[k].x(), tileU - 0.06) << "face " << f;
            EXPECT_LT(uv[k].x(), tileU + 1 / 3.0 + 0.06) << "face " << f;
            EXPECT_GT(uv[k].y(), tileV - 0.06) << "face " << f;
            EXPECT_LT(uv[k].y(), tileV + 0.5 + 0.06) << "face " << f;
        }
        // Not degenerate, not flipped, not stretched: UV area per 3D area near the charts' own.
        const Face& t = output.faces[f];
        const double ratio = signedUvArea(uv[0], uv[1], uv[2]) / faceArea(output, f) / kCubeUvPerArea;
        EXPECT_GT(ratio, 0.3) << "face " << f;
        EXPECT_LT(ratio, 1.01) << "face " << f;
        // A face inside one side of the cube is mapped exactly by that side's chart.
        int side = -1;
        for (int c = 0; c < 6 && side < 0; ++c) {
            const int axis = c / 2;
            const double value = c % 2 ? 1.0 : -1.0;
            bool inside = true;
            for (int v : t)
                inside = inside && output.vertices[v][axis] == value && std::fabs(output.vertices[v][(axis + 1) % 3]) < 1 &&
                         std::fabs(output.vertices[v][(axis + 2) % 3]) < 1;
            if (inside) side = c;
        }
        seamFaces += side < 0;
        if (side >= 0)
            for (int k = 0; k < 3; ++k) EXPECT_LT((uv[k] - cubeUv(side, output.vertices[t[k]])).norm(), 1e-12) << "face " << f;
    }
    EXPECT_GE(seamFaces, r.continuedFaces);
}

TEST(TextureTransfer, ChartsFollowMaterialsAndCoordinates)
{
    TexturedCube cube = texturedCube(3);
    int count = 0;
    std::vector<int> chart = textureCharts(cube.mesh, cube.texture, 0.0, &count);
    EXPECT_EQ(count, 6);
    EXPECT_EQ(chart[0], 0);
    // A second material on one face of a side makes it a chart of its own.
    cube.texture.materials.push_back({"other", ""});
    cube.texture.faceMaterial[8] = 1;  // in the middle of its side: the rest stays connected
    chart = textureCharts(cube.mesh, cube.texture, 0.0, &count);
    EXPECT_EQ(count, 7);
}

TEST(TextureTransfer, SameCoordinatesOnAnyThreadCount)
{
    const TexturedCube cube = texturedCube(6);
    const TriMesh output = sphereOnCube();
    TextureTransferParams params;
    params.threads = 1;
    const TextureTransferResult one = transferTexture(cube.mesh, cube.texture, output, params);
    for (int threads : {2, 3}) {
        params.threads = threads;
        const TextureTransferResult r = transferTexture(cube.mesh, cube.texture, output, params);
        EXPECT_EQ(r.texture.uv, one.texture.uv);
        EXPECT_EQ(r.texture.faceMaterial, one.texture.faceMaterial);
        EXPECT_EQ(r.continuedFaces, one.continuedFaces);
    }
}

//! An open cylinder of n x m cells, its texture one chart cut open along the line at angle 0
//! (u = i / n, the last column's corners at u = 1); `phase` turns the vertices (in cells).
TriMesh cutCylinder(int n, int m, double phase, MeshTexture* texture)
{
    TriMesh c;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= m; ++j) {
            const double a = 2 * M_PI * (i + phase) / n;
            c.vertices.emplace_back(std::cos(a), std::sin(a), 2.0 * j / m);
        }
    const auto v = [&](int i, int j) { return (i % n) * (m + 1) + j; };
    if (texture) texture->materials = {{"", ""}};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const std::array<std::array<int, 2>, 6> corners = {
                {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}}};
            for (int t = 0; t < 2; ++t) {
                c.faces.push_back({v(corners[3 * t][0], corners[3 * t][1]), v(corners[3 * t + 1][0], corners[3 * t + 1][1]),
                                   v(corners[3 * t + 2][0], corners[3 * t + 2][1])});
                if (!texture) continue;
                for (int k = 0; k < 3; ++k)
                    texture->uv.emplace_back(double(corners[3 * t + k][0]) / n, double(corners[3 * t + k][1]) / m);
                texture->faceMaterial.push_back(0);
            }
        }
    return c;
}

TEST(TextureTransfer, FacesAcrossASeamInsideOneChartAreContinued)
{
    MeshTexture texture;
    const TriMesh input = cutCylinder(24, 6, 0.0, &texture), output = cutCylinder(17, 5, 0.5, nullptr);
    const TextureTransferResult r = transferTexture(input, texture, output);
    EXPECT_EQ(r.charts, 1);  // one chart that meets itself along the cut
    // The faces across the cut (one column of 17) are continued: none spans the atlas.
    EXPECT_GE(r.continuedFaces, 10);
    for (int f = 0; f < output.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            EXPECT_LT(std::abs(r.texture.uv[3 * f + k].x() - r.texture.uv[3 * f + (k + 1) % 3].x()), 2.0 / 17)
                << "face " << f << " spans the atlas";
}

}  // namespace
}  // namespace fieldcvt
