// Input validation and repair before any work: clear errors, never a crash.
#include "errors.h"
#include "mesh_check.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <limits>

using namespace fieldcvt;

namespace {

std::string errorOf(const TriMesh& mesh)
{
    InputReport report;
    try {
        prepareInput(mesh, report);
    } catch (const InvalidInputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(MeshCheck, RejectsEmptyMeshAndPointCloud)
{
    EXPECT_NE(errorOf(TriMesh{}).find("empty"), std::string::npos);
    TriMesh cloud;
    cloud.vertices = {{0, 0, 0}, {1, 0, 0}};
    EXPECT_NE(errorOf(cloud).find("point cloud"), std::string::npos);
}

TEST(MeshCheck, RejectsNonFiniteCoordinatesAndBadIndices)
{
    TriMesh m = testmesh::planeGrid(2);
    m.vertices[4].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(errorOf(m).find("vertex 4 has a non-finite coordinate"), std::string::npos);
    TriMesh bad = testmesh::planeGrid(2);
    bad.faces[0][1] = 99;
    EXPECT_NE(errorOf(bad).find("refers to vertex 99"), std::string::npos);
}

TEST(MeshCheck, RejectsNonManifoldEdgeWithCountAndLocation)
{
    TriMesh m = testmesh::planeGrid(1);  // two triangles sharing the diagonal (0, 3)
    m.vertices.emplace_back(0.5, 0.5, 1.0);
    m.faces.push_back({0, 3, 4});
    const std::string error = errorOf(m);
    EXPECT_NE(error.find("1 non-manifold edge"), std::string::npos) << error;
    EXPECT_NE(error.find("vertices 0"), std::string::npos) << error;
}

TEST(MeshCheck, RemovesUnreferencedDegenerateAndDuplicateFaces)
{
    TriMesh m = testmesh::planeGrid(2);
    m.vertices.emplace_back(5, 5, 5);           // unreferenced
    m.faces.push_back({0, 0, 1});               // repeated corner
    m.faces.push_back({0, 1, 2});               // collinear: zero area
    m.faces.push_back(m.faces[0]);              // duplicate
    InputReport report;
    const TriMesh clean = prepareInput(m, report);
    EXPECT_EQ(report.removedUnreferencedVertices, 1);
    EXPECT_EQ(report.removedDegenerateFaces, 2);
    EXPECT_EQ(report.removedDuplicateFaces, 1);
    EXPECT_EQ(clean.faceCount(), 8);
    EXPECT_EQ(clean.vertexCount(), 9);
    EXPECT_EQ(report.notes.size(), 3u);
}
