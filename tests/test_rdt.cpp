// Output mesh extraction from the restricted Delaunay triangles.
#include "metrics.h"
#include "rdt.h"
#include "rvd.h"
#include "sampling.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <omp.h>

using namespace fieldcvt;

TEST(Rdt, BowtieVertexIsSplitIntoOneVertexPerFan)
{
    // Two triangles touching only at vertex 0 (a restricted cell in two pieces).
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 3, 4}};
    std::vector<int> seedOfVertex = {10, 11, 12, 13, 14};
    EXPECT_EQ(computeTopology(m).nonManifoldVertices, 1);
    EXPECT_EQ(splitNonManifoldVertices(m, seedOfVertex), 1);
    EXPECT_EQ(computeTopology(m).nonManifoldVertices, 0);
    ASSERT_EQ(m.vertexCount(), 6);
    EXPECT_EQ(m.vertices[5], m.vertices[0]);
    EXPECT_EQ(seedOfVertex[5], 10);
    EXPECT_EQ(m.faces[1][0], 5);
}

TEST(Rdt, ManifoldFanIsLeftAlone)
{
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    m.faces = {{0, 1, 2}, {0, 2, 3}};
    std::vector<int> seedOfVertex = {0, 1, 2, 3};
    EXPECT_EQ(splitNonManifoldVertices(m, seedOfVertex), 0);
    EXPECT_EQ(m.vertexCount(), 4);
}

TEST(Rdt, FacesOnOverfullEdgesAreRemovedAndUnusedSamplesDropped)
{
    // Three triangles on edge (0, 1) cannot all stay; sample 5 is in no triangle.
    std::vector<Vec3> seeds = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}, {9, 9, 9}};
    TriMesh surface;
    surface.vertices = {{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}};
    surface.faces = {{0, 1, 2}};
    ClosestPointTree tree(surface);
    const RdtResult r = extractRdt(seeds, {{0, 1, 2}, {1, 0, 3}, {0, 4, 1}}, tree);
    EXPECT_EQ(r.removedFaces, 3);  // every face touches the over-full edge
    EXPECT_GE(r.droppedSeeds, 1);
    EXPECT_FALSE(r.warnings.empty());
}

namespace {

// Two parallel unit squares `gap` apart, facing away from each other (the two sides of a thin
// sheet without its rim): the top one at z = 0 facing +z, the bottom one at z = -gap facing -z.
TriMesh twoSheets(double gap)
{
    TriMesh top = testmesh::planeGrid(10), bottom = testmesh::planeGrid(10);
    TriMesh m = top;
    const int offset = m.vertexCount();
    for (Vec3 p : bottom.vertices) m.vertices.push_back(p - Vec3(0, 0, gap));
    for (const Face& f : bottom.faces) m.faces.push_back({f[0] + offset, f[2] + offset, f[1] + offset});
    return m;
}

// A triangular lattice of spacing h over the unit square at height z.
std::vector<Vec3> lattice(double h, double z)
{
    std::vector<Vec3> seeds;
    for (int j = 0; (j + 0.5) * h * std::sqrt(3.0) / 2 < 1.0; ++j)
        for (int i = 0; (i + 0.25 + 0.5 * (j % 2)) * h < 1.0; ++i)
            seeds.emplace_back((i + 0.25 + 0.5 * (j % 2)) * h, (j + 0.5) * h * std::sqrt(3.0) / 2, z);
    return seeds;
}

}  // namespace

TEST(Rdt, CellsSpanningNearTouchingSheetsGetOneVertexPerPiece)
{
    // Samples on the top sheet only, 0.1 apart, 0.02 above the bottom one: every cell covers a
    // patch of each sheet (a cell in two pieces). On samples alone the two patches would share
    // vertices, so every RDT edge would have four faces; one vertex per piece gives two disks.
    const TriMesh surface = twoSheets(0.02);
    const std::vector<Vec3> seeds = lattice(0.1, 0.0);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    rvd.compute(seeds, options, result);
    ASSERT_EQ(result.pieceSeed.size(), 2 * seeds.size());
    // Each RVD vertex is on both sheets, with opposite orientations: as many triangles on
    // samples (both orientations, listed apart) as on pieces.
    EXPECT_EQ(result.pieceTriangles.size(), result.triangles.size());
    for (size_t p = 0; p < result.pieceSeed.size(); ++p) {
        const Vec3& x = seeds[result.pieceSeed[p]];
        const Vec3& q = result.piecePoint[p];
        EXPECT_TRUE((q - x).norm() < 1e-12 || (q - (x - Vec3(0, 0, 0.02))).norm() < 1e-12) << "piece " << p;
    }

    ClosestPointTree tree(surface);
    const RdtResult rdt = extractRdt(seeds, result, tree);
    EXPECT_EQ(rdt.removedFaces, 0);
    EXPECT_EQ(rdt.splitVertices, 0);
    EXPECT_EQ(rdt.multiPieceSeeds, static_cast<int>(seeds.size()));
    const TopologySummary topology = computeTopology(rdt.mesh);
    EXPECT_TRUE(topology.manifold());
    EXPECT_TRUE(topology.orientable);
    EXPECT_EQ(topology.components, 2);
    EXPECT_EQ(topology.boundaryLoops, 2);
    EXPECT_EQ(topology.genus, 0);
    EXPECT_EQ(topology.vertices, 2 * static_cast<int>(seeds.size()));
    // Every output vertex is on its own sheet, with the normal of that sheet.
    for (const Face& f : rdt.mesh.faces) {
        const Vec3 a = rdt.mesh.vertices[f[0]], b = rdt.mesh.vertices[f[1]], c = rdt.mesh.vertices[f[2]];
        EXPECT_EQ(a.z(), b.z());
        EXPECT_EQ(a.z(), c.z());
        EXPECT_GT((b - a).cross(c - a).z() * (a.z() == 0 ? 1 : -1), 0);
    }

    // The samples alone cannot separate the sheets.
    const RdtResult merged = extractRdt(seeds, result.triangles, tree);
    EXPECT_GT(merged.removedFaces, 0);
}

TEST(Rdt, ThinSlabIsRecoveredAsOneClosedSurface)
{
    // A closed slab 1 x 1 x 0.03 sampled at spacing 0.08: the cells of samples on one face
    // reach through to the other (most cells are in two pieces, some RVD vertices lie on input
    // edges). On samples alone the RDT is torn everywhere; on pieces it is one closed surface.
    TriMesh slab;
    const double t = 0.03;
    for (int k = 0; k < 8; ++k) slab.vertices.emplace_back(k & 1 ? 1.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? t : 0.0);
    slab.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                  {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    // Refine by midpoint subdivision so the RVD has more than 12 triangles to walk.
    for (int level = 0; level < 3; ++level) {
        TriMesh fine;
        fine.vertices = slab.vertices;
        std::map<std::pair<int, int>, int> mid;
        auto m = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            fine.vertices.push_back(0.5 * (slab.vertices[a] + slab.vertices[b]));
            return mid[key] = fine.vertexCount() - 1;
        };
        for (const Face& f : slab.faces) {
            const int ab = m(f[0], f[1]), bc = m(f[1], f[2]), ca = m(f[2], f[0]);
            fine.faces.push_back({f[0], ab, ca});
            fine.faces.push_back({f[1], bc, ab});
            fine.faces.push_back({f[2], ca, bc});
            fine.faces.push_back({ab, bc, ca});
        }
        slab = fine;
    }
    // Lattices on both big faces (the bottom one turned by a half turn, so the two do not line
    // up), and samples on the rim.
    std::vector<Vec3> seeds = lattice(0.08, t);
    for (Vec3 p : lattice(0.08, 0.0)) seeds.push_back(Vec3(1.0 - p.x(), 1.0 - p.y(), 0.0));
    for (int k = 0; k < 25; ++k) {
        const double u = (k + 0.5) / 25;
        for (const Vec3& p : {Vec3(u, 0, t / 2), Vec3(u, 1, t / 2), Vec3(0, u, t / 2), Vec3(1, u, t / 2)}) seeds.push_back(p);
    }
    RestrictedVoronoiDiagram rvd(slab);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    rvd.compute(seeds, options, result);
    EXPECT_GT(result.pieceSeed.size(), seeds.size()) << "some cells are in several pieces";
    ClosestPointTree tree(slab);
    const RdtResult rdt = extractRdt(seeds, result, tree);
    const TopologySummary topology = computeTopology(rdt.mesh);
    EXPECT_EQ(rdt.removedFaces, 0);
    EXPECT_TRUE(topology.manifold());
    EXPECT_EQ(topology.components, 1);
    EXPECT_EQ(topology.boundaryLoops, 0);
    EXPECT_EQ(topology.genus, 0);
    EXPECT_GT(extractRdt(seeds, result.triangles, tree).removedFaces, 100);
}

TEST(Rdt, PiecesDoNotDependOnThreadCount)
{
    const TriMesh surface = twoSheets(0.03);
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 300, 4);
    RestrictedVoronoiDiagram rvd(surface);
    RvdOptions options;
    options.triangles = true;
    RvdResult one, two;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    rvd.compute(seeds, options, one);
    omp_set_num_threads(2);
    rvd.compute(seeds, options, two);
    omp_set_num_threads(threads);
    EXPECT_EQ(one.pieceSeed, two.pieceSeed);
    EXPECT_EQ(one.pieceTriangles, two.pieceTriangles);
    ASSERT_EQ(one.piecePoint.size(), two.piecePoint.size());
    for (size_t p = 0; p < one.piecePoint.size(); ++p) EXPECT_EQ(one.piecePoint[p], two.piecePoint[p]);
}
