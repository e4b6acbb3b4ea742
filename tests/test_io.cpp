// Mesh file reading and writing (io/): every format, round trips, and broken files that must
// give an IOError, never a crash.
#include "temp_dir_test.h"
#include "errors.h"
#include "mesh_io.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

namespace fieldcvt {
namespace {

namespace fs = std::filesystem;

//! A fresh directory per test for the files it writes (temp_dir_test.h).
class IoTest : public TempDirTest {};

//! The unit square as two triangles, in the order every reader below must reproduce.
void expectSquare(const TriMesh& m)
{
    ASSERT_EQ(m.vertexCount(), 4);
    ASSERT_EQ(m.faceCount(), 2);
    EXPECT_EQ(m.vertices[2], Vec3(1, 1, 0));
    EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
    EXPECT_EQ(m.faces[1], (Face{0, 2, 3}));
}

std::string plyHeader(const std::string& format, int vertices, int faces)
{
    return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string binarySquarePly()
{
    std::string s = plyHeader("binary_little_endian", 4, 2);
    const float v[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    s.append(reinterpret_cast<const char*>(v), sizeof v);
    for (const auto& f : {std::array<std::int32_t, 3>{0, 1, 2}, std::array<std::int32_t, 3>{0, 2, 3}}) {
        s.push_back(3);
        s.append(reinterpret_cast<const char*>(f.data()), 12);
    }
    return s;
}

std::string binarySquareStl()
{
    std::string s(80, ' ');
    const std::uint32_t n = 2;
    s.append(reinterpret_cast<const char*>(&n), 4);
    const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& t : tris) {
        s.append(reinterpret_cast<const char*>(t), sizeof t);
        s.append(2, '\0');
    }
    return s;
}

const char* asciiSquareStl =
    "solid square\n"
    " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 1 1 0\n  endloop\n endfacet\n"
    " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n  endloop\n endfacet\n"
    "endsolid square\n";

TEST_F(IoTest, ObjWithNormalsSlashSlashAndCrlf)
{
    const auto file = write("n.obj",
                            "# exported\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
                            "vn 0 0 1\r\nvn 0 0 1\r\nvn 0 0 1\r\nvn 0 0 1\r\n"
                            "s off\r\nf 1//1 2//2 3//3\r\nf 1//1 3//3 4//4\r\n");
    MeshReadInfo info;
    expectSquare(readMesh(file, &info));
    EXPECT_EQ(info.polygonsTriangulated, 0);
}

TEST_F(IoTest, ObjQuadsNegativeIndicesAndTexCoords)
{
    const auto file = write("q.OBJ",
                            "v 0 0 0\nv 1 0 0\nv 1 1 0   # trailing comment\nv 0 1 0\nvt 0 0\n"
                            "f -4/1 -3/1/1 -2/1/1 -1/1\n"
                            "v 2 0 0\nf 2 5 3\n");
    MeshReadInfo info;
    const TriMesh m = readMesh(file, &info);
    ASSERT_EQ(m.faceCount(), 3);
    EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
    EXPECT_EQ(m.faces[1], (Face{0, 2, 3}));
    EXPECT_EQ(m.faces[2], (Face{1, 4, 2}));
    EXPECT_EQ(info.polygonsTriangulated, 1);
    EXPECT_FALSE(info.notes.empty());
}

TEST_F(IoTest, ObjKeepsUnreferencedVertices)
{
    const TriMesh m = readMesh(write("u.obj", "v 0 0 0\nv 1 0 0\nv 9 9 9\nv 1 1 0\nf 1 2 4\n"));
    EXPECT_EQ(m.vertexCount(), 4);
    EXPECT_EQ(m.faces[0], (Face{0, 1, 3}));
}

TEST_F(IoTest, AsciiPly)
{
    expectSquare(readMesh(write("a.ply", plyHeader("ascii", 4, 2) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")));
}

TEST_F(IoTest, BinaryPly) { expectSquare(readMesh(write("b.ply", binarySquarePly()))); }

TEST_F(IoTest, PlyQuadIsTriangulatedAndCounted)
{
    MeshReadInfo info;
    const TriMesh m = readMesh(write("q.ply", plyHeader("ascii", 4, 1) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"), &info);
    EXPECT_EQ(m.faceCount(), 2);
    EXPECT_EQ(info.polygonsTriangulated, 1);
}

TEST_F(IoTest, Off)
{
    expectSquare(readMesh(write("s.off", "OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3 255 0 0\n")));
    MeshReadInfo info;
    expectSquare(readMesh(write("q.off", "OFF 4 1 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n4 0 1 2 3\r\n"), &info));
    EXPECT_EQ(info.polygonsTriangulated, 1);
}

TEST_F(IoTest, StlAsciiAndBinaryWeldVertices)
{
    for (const auto& file : {write("a.stl", asciiSquareStl), write("b.stl", binarySquareStl())}) {
        SCOPED_TRACE(file);
        MeshReadInfo info;
        expectSquare(readMesh(file, &info));
        EXPECT_EQ(info.notes.size(), 1u);  // the welding is reported
    }
}

TEST_F(IoTest, RoundTripEveryFormat)
{
    const TriMesh torus = testmesh::torus(12, 8);
    for (const std::string ext : {"ply", "obj", "off", "stl"}) {
        SCOPED_TRACE(ext);
        const auto file = path("t." + ext);
        writeMesh(file, torus);
        const TriMesh back = readMesh(file);
        ASSERT_EQ(back.vertexCount(), torus.vertexCount());
        ASSERT_EQ(back.faceCount(), torus.faceCount());
        // Corner by corner (STL renumbers vertices when it welds them, and stores floats).
        const double tolerance = ext == "stl" ? 1e-6 : 1e-15;
        for (int f = 0; f < torus.faceCount(); ++f)
            for (int k = 0; k < 3; ++k)
                ASSERT_LT((back.vertices[back.faces[f][k]] - torus.vertices[torus.faces[f][k]]).norm(), tolerance);
        // Writing is byte-deterministic.
        writeMesh(path("again." + ext), torus);
        EXPECT_EQ(bytes(file), bytes(path("again." + ext)));
    }
}

TEST_F(IoTest, PlyWithAttributes)
{
    const TriMesh grid = testmesh::planeGrid(2);
    VertexAttributes attributes;
    attributes.normals.assign(grid.vertices.size(), Vec3(0, 0, 1));
    attributes.rosy.assign(grid.vertices.size(), Vec3(1, 0, 0));
    const auto file = path("attr.ply");
    writeMesh(file, grid, &attributes);
    const std::string content = bytes(file);
    EXPECT_NE(content.find("property float rosy_x\nproperty float rosy_y\nproperty float rosy_z\n"), std::string::npos);
    EXPECT_NE(content.find("property float nx\n"), std::string::npos);
    EXPECT_EQ(readMesh(file).faces, grid.faces);  // readers skip the extra properties

    attributes.rosy.pop_back();
    EXPECT_THROW(writeMesh(file, grid, &attributes), IOError);
}

TEST_F(IoTest, PlyAttributesAreReadBack)
{
    const TriMesh grid = testmesh::planeGrid(3);
    VertexAttributes written;
    for (std::size_t v = 0; v < grid.vertices.size(); ++v) {
        written.normals.push_back(Vec3(0, 0, 1));
        written.rosy.push_back(Vec3(std::cos(0.1 * v), std::sin(0.1 * v), 0));
    }
    const auto file = path("attr.ply");
    writeMesh(file, grid, &written);
    VertexAttributes read;
    MeshReadInfo info;
    const TriMesh back = readMesh(file, &info, &read);
    EXPECT_EQ(back.faces, grid.faces);
    ASSERT_EQ(read.normals.size(), grid.vertices.size());
    ASSERT_EQ(read.rosy.size(), grid.vertices.size());
    for (std::size_t v = 0; v < grid.vertices.size(); ++v) {
        EXPECT_EQ(read.normals[v], written.normals[v].cast<float>().cast<double>());
        EXPECT_EQ(read.rosy[v], written.rosy[v].cast<float>().cast<double>());  // stored as float
    }
    EXPECT_TRUE(info.notes.empty());

    // Only the normals: rosy stays empty; a later call clears what an earlier one filled.
    VertexAttributes normalsOnly;
    normalsOnly.normals = written.normals;
    writeMesh(file, grid, &normalsOnly);
    readMesh(file, nullptr, &read);
    EXPECT_EQ(read.normals.size(), grid.vertices.size());
    EXPECT_TRUE(read.rosy.empty());

    // Other formats carry no attributes back.
    writeMesh(path("attr.obj"), grid, &written);
    readMesh(path("attr.obj"), nullptr, &read);
    EXPECT_TRUE(read.normals.empty() && read.rosy.empty());
}

TEST_F(IoTest, AsciiPlyRosyInAnyOrderAndIncompleteGroups)
{
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float rosy_z\nproperty float x\nproperty float rosy_x\n"
        "property float y\nproperty uchar red\nproperty float z\nproperty float rosy_y\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n";
    const std::string body = "0 0 1 0 9 0 0\n0 1 1 0 9 0 0\n0 1 0 1 9 0 1\n0 0 0 1 9 0 1\n3 0 1 2\n3 0 2 3\n";
    VertexAttributes read;
    expectSquare(readMesh(write("r.ply", header + body), nullptr, &read));
    ASSERT_EQ(read.rosy.size(), 4u);
    EXPECT_EQ(read.rosy[0], Vec3(1, 0, 0));
    EXPECT_EQ(read.rosy[2], Vec3(0, 1, 0));
    EXPECT_TRUE(read.normals.empty());

    // rosy_x and rosy_y without rosy_z: not used, and said so.
    const std::string partial =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nproperty float rosy_x\nproperty float rosy_y\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n"
        "0 0 0 1 0\n1 0 0 1 0\n1 1 0 1 0\n0 1 0 1 0\n3 0 1 2\n3 0 2 3\n";
    MeshReadInfo info;
    expectSquare(readMesh(write("p.ply", partial), &info, &read));
    EXPECT_TRUE(read.rosy.empty());
    ASSERT_EQ(info.notes.size(), 1u);
    EXPECT_NE(info.notes[0].find("rosy_x"), std::string::npos);
}

TEST_F(IoTest, WriteErrors)
{
    const TriMesh grid = testmesh::planeGrid(1);
    EXPECT_THROW(writeMesh(path("x.xyz"), grid), IOError);
    for (const std::string ext : {"ply", "obj", "off", "stl"})
        EXPECT_THROW(writeMesh(path("missing/dir/x." + ext), grid), IOError);
}

//! Each broken file must throw an IOError whose one-line message names the file.
void expectIoError(const std::string& file, const std::string& fragment = "")
{
    try {
        readMesh(file);
        ADD_FAILURE() << file << " was read without error";
    } catch (const IOError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(file), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
}

TEST_F(IoTest, MissingEmptyAndUnknownFiles)
{
    expectIoError(path("none.obj"), "no such file");
    expectIoError(write("e.obj", ""), "empty");
    expectIoError(write("e.ply", ""), "empty");
    expectIoError(write("m.xyz", "v 0 0 0\n"), "extension");
    expectIoError(dir_.string() + "/", "extension");
    fs::create_directories(path("dir.obj"));
    expectIoError(path("dir.obj"), "directory");
}

// Issue 14: valid files that were refused or read short.
TEST_F(IoTest, PlyCommentMentioningEndHeaderDoesNotEndTheHeader)
{
    const std::string header = plyHeader("ascii", 4, 2);
    std::string ply = header;
    ply.insert(ply.find("element"), "comment the words end_header in a comment\nobj_info end_header too\n");
    expectSquare(readMesh(write("c.ply", ply + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")));
}

TEST_F(IoTest, PlyDataAfterTheDeclaredFacesIsReported)
{
    for (const bool binary : {false, true}) {
        SCOPED_TRACE(binary ? "binary" : "ascii");
        std::string ply =
            binary ? binarySquarePly() : plyHeader("ascii", 4, 2) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
        ply += binary ? std::string("\x03\0\0\0\0\x01\0\0\0\x02\0\0\0", 13) : "3 0 1 3\n\n3 1 2 3\n";
        MeshReadInfo info;
        expectSquare(readMesh(write("x.ply", ply), &info));
        ASSERT_EQ(info.warnings.size(), 1u);  // data ignored: the mesh differs from the file
        EXPECT_NE(info.warnings[0].find(binary ? "13 bytes ignored" : "2 lines ignored"), std::string::npos) << info.warnings[0];
        EXPECT_NE(info.warnings[0].find("4 vertex, 2 face"), std::string::npos) << info.warnings[0];
    }
}

TEST_F(IoTest, ByteOrderMarkIsSkipped)
{
    const std::string bom = "\xEF\xBB\xBF";
    expectSquare(readMesh(write("b.obj", bom + "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n")));
    expectSquare(readMesh(write("b.off", bom + "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")));
    expectSquare(readMesh(write("b.ply", bom + binarySquarePly())));
    expectSquare(readMesh(write("b.stl", bom + asciiSquareStl)));
}

TEST_F(IoTest, ObjBackslashContinuesTheLine)
{
    expectSquare(readMesh(write("c.obj", "v 0 0 \\\n 0\nv 1 0 0\r\nv 1 1 0\nv 0 1 0\nf 1 2 \\ \r\n 3\nf 1\\\n3 4\n")));
    expectIoError(write("d.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 \\\n"), "fewer than 3 corners");
}

TEST_F(IoTest, AsciiStlEndingRightAfterItsLastFacetKeepsIt)
{
    std::string stl = asciiSquareStl;
    stl = stl.substr(0, stl.find("endsolid"));
    stl.erase(stl.find_last_not_of("\n") + 1);  // "... endfacet" and nothing after it
    MeshReadInfo info;
    expectSquare(readMesh(write("n.stl", stl), &info));
    ASSERT_EQ(info.warnings.size(), 1u);  // truncated?
    EXPECT_NE(info.warnings[0].find("without 'endsolid'"), std::string::npos) << info.warnings[0];
    ASSERT_EQ(info.notes.size(), 1u);  // the STL's shared corners merged
    EXPECT_NE(info.notes[0].find("duplicate STL vertices"), std::string::npos) << info.notes[0];
    // Two solids in one file, and a facet cut short: every facet whole, or an error.
    const std::string second = std::string(asciiSquareStl).replace(0, 12, "solid again");
    EXPECT_EQ(readMesh(write("two.stl", std::string(asciiSquareStl) + second)).faceCount(), 4);
    expectIoError(write("cut.stl", std::string(asciiSquareStl).substr(0, std::string(asciiSquareStl).rfind("endloop"))),
                  "unexpected end of file");
}

TEST_F(IoTest, PolygonsWithStraightCornersGetNoZeroAreaTriangles)
{
    // A square face with a vertex on two of its edges (180-degree corners), as OBJ, OFF and PLY;
    // the fan from corner 0 made (0, 1, 2) of zero area.
    const std::string points = "0 0 0\n1 0 0\n2 0 0\n2 2 0\n1 2 0\n0 2 0\n";
    std::string obj;
    for (std::size_t i = 0; i < points.size();) {
        const std::size_t end = points.find('\n', i);
        obj += "v " + points.substr(i, end - i) + "\n";
        i = end + 1;
    }
    for (const auto& file : {write("p.obj", obj + "f 1 2 3 4 5 6\n"), write("p.off", "OFF\n6 1 0\n" + points + "6 0 1 2 3 4 5\n"),
                             write("p.ply", plyHeader("ascii", 6, 1) + points + "6 0 1 2 3 4 5\n")}) {
        SCOPED_TRACE(file);
        const TriMesh m = readMesh(file);
        ASSERT_EQ(m.faceCount(), 4);
        double area = 0;
        for (int f = 0; f < m.faceCount(); ++f) {
            EXPECT_GT(faceArea(m, f), 0.1) << "face " << f;
            EXPECT_GT(faceNormal(m, f).z(), 0) << "face " << f;  // the polygon's orientation
            area += faceArea(m, f);
        }
        EXPECT_DOUBLE_EQ(area, 4.0);
    }
}

TEST_F(IoTest, BrokenObj)
{
    expectIoError(write("g.obj",
                        "\x7f"
                        "ELF garbage \x01\x02\n"),
                  "no faces");
    expectIoError(write("r.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n"), "line 4");
    expectIoError(write("z.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n"), "does not exist");
    expectIoError(write("n.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0x\nf 1 2 3\n"), "malformed number");
    expectIoError(write("i.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3abc\n"), "malformed integer");
    expectIoError(write("p.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n"), "no faces");
    expectIoError(write("s.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), "fewer than 3");
}

TEST_F(IoTest, BrokenOff)
{
    const std::string square = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
    for (std::size_t cut : {4ul, 10ul, 20ul, square.size() - 8})
        expectIoError(write("t" + std::to_string(cut) + ".off", square.substr(0, cut)));
    expectIoError(write("t.off", square.substr(0, square.size() - 8)), "end of file");
    expectIoError(write("r.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 3\n"), "out of range");
    expectIoError(write("k.off", "PLY\n3 1 0\n"), "not an OFF file");
    expectIoError(write("c.off", "OFF\n-3 1 0\n"), "count");
    expectIoError(write("n.off", "OFF\n3 1 0\n0 0 0\n1 0 zero\n1 1 0\n3 0 1 2\n"), "line 4");
}

TEST_F(IoTest, BrokenPly)
{
    const std::string binary = binarySquarePly();
    expectIoError(write("t.ply", binary.substr(0, binary.size() - 5)));
    const std::string ascii = plyHeader("ascii", 4, 2) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
    expectIoError(write("ta.ply", ascii.substr(0, ascii.size() - 9)));
    expectIoError(write("h.ply", binary.substr(0, 30)));
    expectIoError(write("r.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n1 1 0\n3 0 1 7\n"));
    // An index no integer type holds is named as read (converting it was undefined behaviour).
    expectIoError(write("rh.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n1 1 0\n3 0 1 4.5e114\n"),
                  "vertex index 4.5e+114 out of range");
    expectIoError(write("rf.ply", plyHeader("ascii", 3, 1) + "0 0 0\n1 0 0\n1 1 0\n3 0 1 1.5\n"),
                  "vertex index 1.5 out of range");
    expectIoError(write("g.ply", "garbage\n"));
    expectIoError(write("e.ply", "ply\nformat ascii 1.0\nelement vertex\nend_header\n"), "malformed PLY header");
    expectIoError(write("p.ply", plyHeader("ascii", 3, 0) + "0 0 0\n1 0 0\n1 1 0\n"), "no faces");
    expectIoError(write("huge.ply", plyHeader("binary_little_endian", 2000000000, 2000000000)), "truncated");
    expectIoError(write("hugea.ply", plyHeader("ascii", 2000000000, 1) + "0 0 0\n"), "truncated");
}

TEST_F(IoTest, BrokenStl)
{
    const std::string binary = binarySquareStl();
    expectIoError(write("t.stl", binary.substr(0, binary.size() - 7) + "\xff"), "truncated");
    expectIoError(write("h.stl", binary.substr(0, 50)));
    expectIoError(write("l.stl", "solid but no line end"));
    const std::string ascii = asciiSquareStl;
    expectIoError(write("ta.stl", ascii.substr(0, ascii.find("vertex 1 1 0") + 9)));
    expectIoError(write("g.stl", "solid x\nnothing useful here\n"), "line 2: expected 'facet'");
}

struct BundledMesh {
    const char* name;
    int vertices;
    int faces;
};

TEST_F(IoTest, BundledMeshes)
{
    for (const BundledMesh& b :
         {BundledMesh{"bunny.obj", 35947, 69451}, BundledMesh{"torus.obj", 3072, 6144}, BundledMesh{"fertility.off", 4494, 9000},
          BundledMesh{"cylinder.off", 930, 1800}, BundledMesh{"fandisk.off", 7229, 14454}}) {
        SCOPED_TRACE(b.name);
        MeshReadInfo info;
        const TriMesh m = readMesh(testmesh::resource(b.name), &info);
        EXPECT_EQ(m.vertexCount(), b.vertices);
        EXPECT_EQ(m.faceCount(), b.faces);
        EXPECT_EQ(info.polygonsTriangulated, 0);
    }
}

TEST_F(IoTest, UnderflowingDecimalsAreReadAndOverflowingOnesRefused)
{
    // strtod's reading: 1e-400 is 0, 2.5e-320 a subnormal (issue 30: was "malformed number").
    const std::string tet = "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    const TriMesh zero = readMesh(write("under.obj", "v 1e-400 -1e-400 2.5e-320\n" + tet));
    EXPECT_EQ(zero.vertices[0].x(), 0.0);
    EXPECT_EQ(zero.vertices[0].y(), 0.0);
    EXPECT_TRUE(std::signbit(zero.vertices[0].y()));
    EXPECT_GT(zero.vertices[0].z(), 0.0);
    EXPECT_LT(zero.vertices[0].z(), 1e-300);
    for (const char* huge : {"1e400", "-1e400"}) {
        try {
            readMesh(write("over.obj", std::string("v ") + huge + " 0 0\n" + tet));
            ADD_FAILURE() << huge << " was read";
        } catch (const IOError& e) {
            EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(readMesh(write("bad.obj", "v 1e-4x00 0 0\n" + tet)), IOError);
}

TEST_F(IoTest, SpecialFilesAreRefusedWithoutOpeningThem)
{
    const std::string fifo = path("pipe.off");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    try {
        readMesh(fifo);  // opening it would wait for a writer forever
        ADD_FAILURE() << "a FIFO was read";
    } catch (const IOError& e) {
        EXPECT_NE(std::string(e.what()).find("FIFO"), std::string::npos) << e.what();
    }
}

TEST(Messages, QuotedInputIsBoundedAndEscaped)
{
    EXPECT_EQ(quoteInput("abc"), "'abc'");
    EXPECT_EQ(quoteInput(std::string(1000000, 'x')), "'" + std::string(80, 'x') + "'...");
    EXPECT_EQ(quoteInput(std::string(80, 'y')), "'" + std::string(80, 'y') + "'");
    EXPECT_EQ(quoteInput("\x1b[31mred\n"), "'\\x1B[31mred\\x0A'");
    // A UTF-8 character counts once and is never cut.
    EXPECT_EQ(quoteInput("\xC3\xA9\xC3\xA9\xC3\xA9", 2), "'\xC3\xA9\xC3\xA9'...");
    EXPECT_EQ(escapeControlCharacters("a\tb\x7f"), "a\\x09b\\x7F");
}

}  // namespace
}  // namespace fieldcvt
