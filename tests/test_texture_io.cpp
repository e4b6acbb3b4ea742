// Texture coordinates in the OBJ and PLY readers and writers (issue 36): per-corner `vt`, negative
// indices, materials, MeshLab's `texcoord` / `texnumber` / `TextureFile`, broken ones dropped.
#include "temp_dir_test.h"
#include "mesh_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

namespace fieldcvt {
namespace {

namespace fs = std::filesystem;

//! A fresh directory per test for the files it writes (temp_dir_test.h).
class TextureIoTest : public TempDirTest {};

//! Two triangles and a quad, three materials (the first faces before any usemtl), a seam at
//! vertex 2 (two vt), negative and positive indices.
const char* kTexturedObj =
    "mtllib a.mtl b.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
    "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\n"
    "f 1/1 2/2 3/3\n"
    "usemtl red\n"
    "f -6/-4/1 -4/-2 -3/-1\n"
    "vt 0.9 0.1\nvt 0.9 0.9\nvt 0.6 0.9\nvt 0.6 0.1\n"
    "usemtl blue\n"
    "f 2/8 5/5 6/6 3/7\n";

TEST_F(TextureIoTest, ObjKeepsCornersMaterialsAndLibraries)
{
    MeshReadInfo info;
    MeshTexture t;
    const TriMesh m = readMesh(write("t.obj", kTexturedObj), &info, nullptr, &t);
    ASSERT_EQ(m.faceCount(), 4);
    ASSERT_EQ(t.uv.size(), 12u);
    EXPECT_TRUE(info.warnings.empty());
    EXPECT_EQ(t.libraries, (std::vector<std::string>{"a.mtl", "b.mtl"}));
    ASSERT_EQ(t.materials.size(), 3u);
    EXPECT_EQ(t.materials[0].name, "");
    EXPECT_EQ(t.materials[1].name, "red");
    EXPECT_EQ(t.materials[2].name, "blue");
    EXPECT_EQ(t.faceMaterial, (std::vector<int>{0, 1, 2, 2}));
    EXPECT_EQ(t.uv[2], Vec2(0.5, 0.5));
    EXPECT_EQ(t.uv[3], Vec2(0, 0));    // -4 of 4 vt: the first
    EXPECT_EQ(t.uv[5], Vec2(0, 0.5));  // -1
    // The quad's triangles: each corner keeps its own vertex's coordinates (vertex 2 has 0.6 0.9 here).
    const std::map<int, Vec2> quad = {{1, {0.6, 0.1}}, {4, {0.9, 0.1}}, {5, {0.9, 0.9}}, {2, {0.6, 0.9}}};
    for (int f = 2; f < 4; ++f)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(t.uv[3 * f + k], quad.at(m.faces[f][k]));
}

TEST_F(TextureIoTest, BrokenCoordinatesAreDroppedWithAWarning)
{
    for (const std::string& body : {std::string("vt nan 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n"),
                                    std::string("vt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n"),        // index out of range
                                    std::string("vt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3\n"),  // some corners only
                                    std::string("vt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1 3 4\n")}) {
        MeshReadInfo info;
        MeshTexture t;
        const TriMesh m = readMesh(write("b.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + body), &info, nullptr, &t);
        EXPECT_GE(m.faceCount(), 1) << body;
        EXPECT_TRUE(t.empty()) << body;
        ASSERT_EQ(info.warnings.size(), 1u) << body;
        EXPECT_NE(info.warnings[0].find("texture coordinates dropped"), std::string::npos) << info.warnings[0];
    }
    // Without texture coordinates at all: nothing said.
    MeshReadInfo info;
    MeshTexture t;
    readMesh(write("p.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"), &info, nullptr, &t);
    EXPECT_TRUE(t.empty());
    EXPECT_TRUE(info.warnings.empty());
}

//! MeshLab's layout: a triangle with texture 1, a quad (2 triangles) with texture 0, uv = (x, y).
std::string meshLabPly(int firstTexnumber)
{
    return "ply\nformat ascii 1.0\ncomment TextureFile a b.png\ncomment TextureFile c.png\n"
           "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
           "property int texnumber\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
           "3 0 1 2 6 0 0 1 0 1 1 " +
           std::to_string(firstTexnumber) + "\n4 0 1 2 3 8 0 0 1 0 1 1 0 1 0\n";
}

TEST_F(TextureIoTest, MeshLabPlyTexcoordAndTextureFiles)
{
    const std::string ply = meshLabPly(1);
    MeshReadInfo info;
    MeshTexture t;
    const TriMesh m = readMesh(write("m.ply", ply), &info, nullptr, &t);
    ASSERT_EQ(m.faceCount(), 3);  // the quad triangulated
    ASSERT_EQ(t.materials.size(), 2u);
    EXPECT_EQ(t.materials[0].image, "a b.png");
    EXPECT_EQ(t.materials[1].image, "c.png");
    EXPECT_EQ(t.faceMaterial, (std::vector<int>{1, 0, 0}));
    for (int f = 0; f < 3; ++f)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(t.uv[3 * f + k], m.vertices[m.faces[f][k]].head<2>()) << f << " " << k;
    // Round trips through both writers (binary PLY keeps floats: the values above are exact).
    for (const std::string name : {"r.ply", "r.obj"}) {
        MeshTexture named = t;
        named.materials[0].name = "m0", named.materials[1].name = "m1";
        writeMesh(path(name), m, nullptr, &named);
        MeshTexture back;
        const TriMesh again = readMesh(path(name), nullptr, nullptr, &back);
        EXPECT_EQ(again.faces, m.faces) << name;
        EXPECT_EQ(back.uv, t.uv) << name;
        // PLY keeps the texture numbers; OBJ the names (numbered again in the order they come).
        ASSERT_EQ(back.faceMaterial.size(), t.faceMaterial.size());
        for (std::size_t f = 0; f < t.faceMaterial.size(); ++f)
            if (name == "r.ply")
                EXPECT_EQ(back.faceMaterial[f], t.faceMaterial[f]);
            else
                EXPECT_EQ(back.materials[back.faceMaterial[f]].name, named.materials[t.faceMaterial[f]].name);
    }
    EXPECT_NE(bytes(path("r.obj")).find("usemtl m1\nf 1/1 2/2 3/3\nusemtl m0\n"), std::string::npos);
    // A texnumber beyond the TextureFile list: dropped, the mesh read.
    info = MeshReadInfo{};
    EXPECT_EQ(readMesh(write("bad.ply", meshLabPly(7)), &info, nullptr, &t).faceCount(), 3);
    EXPECT_TRUE(t.empty());
    ASSERT_EQ(info.warnings.size(), 1u);
    EXPECT_NE(info.warnings[0].find("texnumber 7 out of range"), std::string::npos) << info.warnings[0];
}

TEST_F(TextureIoTest, ObjWithNormalsAndTexture)
{
    MeshTexture t;
    const TriMesh m = readMesh(write("t.obj", kTexturedObj), nullptr, nullptr, &t);
    VertexAttributes attributes;
    attributes.normals.assign(m.vertices.size(), Vec3(0, 0, 1));
    writeMesh(path("n.obj"), m, &attributes, &t);
    EXPECT_NE(bytes(path("n.obj")).find("\nf 1/1/1 2/2/2 3/3/3\n"), std::string::npos);
    MeshTexture back;
    EXPECT_EQ(readMesh(path("n.obj"), nullptr, nullptr, &back).faces, m.faces);
    EXPECT_EQ(back.uv, t.uv);
}

TEST_F(TextureIoTest, UntexturedFilesAreWrittenAsBefore)
{
    MeshTexture t;
    const TriMesh m = readMesh(write("t.obj", kTexturedObj), nullptr, nullptr, &t);
    for (const std::string name : {"a.ply", "a.obj"}) {
        writeMesh(path("plain_" + name), m);
        const MeshTexture none;
        writeMesh(path("empty_" + name), m, nullptr, &none);
        EXPECT_EQ(bytes(path("plain_" + name)), bytes(path("empty_" + name)));
        EXPECT_EQ(bytes(path("plain_" + name)).find("\nvt "), std::string::npos);
    }
}

}  // namespace
}  // namespace fieldcvt
