// The last step of a run on a coarse copy of the input (core/remesh_stages.h, projectOnInput):
// every vertex onto its closest input point, unless that turns a face into a sliver (where the
// input differs from the copy by more than the mesh resolves: a scan's ragged border, a local
// shell's thin walls; issue 52 item 4), in which case the face's vertices stay on the copy.
#include "closest_point.h"
#include "remesh_stages.h"
#include "test_meshes.h"
#include "triangle_shape.h"

#include <gtest/gtest.h>

using namespace fieldcvt;

namespace {

std::vector<Vec3> project(const TriMesh& mesh, const TriMesh& input)
{
    const ClosestPointTree tree(input);
    const RemeshParams params;
    const Progress progress = [](const std::string&, double) { return true; };  // the pipeline keeps a reference
    Pipeline pipeline(progress, params);
    return projectOnInput(mesh, tree, pipeline);
}

}  // namespace

TEST(ProjectOnInput, EveryVertexGoesOntoAnInputThatFollowsTheCopy)
{
    TriMesh mesh = testmesh::planeGrid(4);
    for (Vec3& p : mesh.vertices) p.z() = 0.01;
    TriMesh input = testmesh::planeGrid(16, 2.0);
    for (Vec3& p : input.vertices) p -= Vec3(0.5, 0.5, 0.0);
    const std::vector<Vec3> projected = project(mesh, input);
    ASSERT_EQ(projected.size(), mesh.vertices.size());
    for (int v = 0; v < mesh.vertexCount(); ++v)
        EXPECT_LT((projected[v] - Vec3(mesh.vertices[v].x(), mesh.vertices[v].y(), 0.0)).norm(), 1e-12);
}

TEST(ProjectOnInput, NoFaceTurnedIntoASliver)
{
    // An input far smaller than the faces: most vertices would land on its corners, faces with
    // two or three vertices on one point. Those stay where they were; none is a new sliver.
    const TriMesh mesh = testmesh::planeGrid(6);
    TriMesh input;
    input.vertices = {Vec3(0.45, 0.45, -0.05), Vec3(0.55, 0.45, -0.05), Vec3(0.5, 0.55, -0.05)};
    input.faces = {{0, 1, 2}};
    const std::vector<Vec3> projected = project(mesh, input);
    const double limit = 15.0 * kPi / 180.0;
    int moved = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v) moved += projected[v] != mesh.vertices[v];
    for (const Face& t : mesh.faces) {
        const double before = smallestAngle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        const double after = smallestAngle(projected[t[0]], projected[t[1]], projected[t[2]]);
        EXPECT_GE(after, std::min(limit, before) - 1e-12);
    }
    // Here the guard had to act (a plain projection puts 40 of the 49 vertices on 3 points).
    EXPECT_LT(moved, mesh.vertexCount());
}
