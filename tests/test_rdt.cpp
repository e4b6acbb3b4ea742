// Output mesh extraction from the restricted Delaunay triangles.
#include "metrics.h"
#include "rdt.h"
#include "rvd.h"
#include "sampling.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <map>
#include <vector>

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

TEST(Rdt, LensPieceAcrossTwoCellsIsDroppedNotTheirEdge)
{
    // Cut from fcvt remesh of nefertiti.obj at 40000 vertices (working frame, translated):
    // the input has a folded triangle (face {12, 10, 7}, its normal opposite to its
    // neighbours'), through which the cell of sample 8 pokes. Besides its main piece, that cell
    // has a small lens on the border of the cells of samples 12 and 13 (the surface crosses
    // their Voronoi edge twice): the triangles (lens, 12, 13) and (lens, 13, 12). Kept, they
    // gave edge (12, 13) four faces, all removed: a hole in a closed output (two on the whole
    // model). The lens is dropped; the edge keeps its two regular faces.
    TriMesh surface;
    surface.vertices = {
        {-0.33870867015035699, 1.4869102439033739, 2.3254128847402527},
        {-0.09481686936336331, 0.8215444245181498, 1.2036915365506573},
        {0.23300414734007191, 1.5106386047793396, 1.8916570275247295},
        {-1.070545361248044, 0.51911144970356915, 1.5770450937397271},
        {0.67933654358069262, 1.1788690008550695, 1.0822278430181385},
        {-1.1774754793761382, -0.56062637394757964, 0.084293940900991515},
        {-2.1594122601446628, -0.5909264211697316, 0.78155709699348819},
        {-0.20297225089869642, 0.22676665393914952, 0.53729824817605021},
        {-2.5666815863386176, -1.3915633783069001, -0.2873986077958719},
        {0.75656165708933898, 0.5528294242906, 0.26782094295217007},
        {2.0364154806884471e-11, 4.8220982762359199e-11, 4.2902570385194849e-11},
        {1.5146854254415878, 1.1704391753384833, 0.51871353777374196},
        {0.50158772711549204, -0.33678050641827006, -0.84294737341389947},
        {1.9215594946696655, 0.96627285677606523, -0.080643372700457405},
        {-2.7597969714780746, -1.9217250976455578, -1.0088822877201551},
        {1.532773658580286, 0.30094088811336128, -0.74239280656328788},
        {-0.56902367624881478, -1.2935608904383109, -1.5242791183838449},
        {1.2473656059735241, -0.15604486149555363, -1.2169643383903761},
        {-1.9068589887007157, -2.0048584897129942, -1.7041499105332036},
        {0.68033182119670599, -0.86475221675791403, -1.962015422323752},
    };
    surface.faces = {
        {0, 1, 2},   {1, 0, 3},   {2, 1, 4},   {1, 3, 5},    {3, 6, 5},   {7, 4, 1},   {1, 5, 7},    {8, 5, 6},
        {9, 7, 10},  {4, 7, 9},   {11, 4, 9},  {12, 10, 7},  {12, 9, 10}, {11, 9, 13}, {12, 7, 5},   {14, 5, 8},
        {15, 13, 9}, {9, 12, 15}, {12, 5, 16}, {17, 15, 12}, {16, 5, 18}, {18, 5, 14}, {17, 12, 19}, {19, 12, 16},
    };
    const std::vector<Vec3> seeds = {
        {-1.9816665365345685, -1.2948279289462459, -0.53477517048764156},
        {-1.9330513835587375, -0.25866157060988826, 1.0165342050242501},
        {0.49132694978685976, -0.93837146357164869, -1.9499946008380888},
        {1.6057581329593731, 1.5126277981869301, 0.87623574454128317},
        {1.0068385939963314, -0.2999089747452004, -1.2655954433890244},
        {-1.4507065882197239, -0.63779240551896876, 0.15215333494501238},
        {0.016494609502863966, -0.66875381695753155, -1.003021342520249},
        {-0.91613942845821583, 0.058490607556430874, 0.77598291128923336},
        {-0.46740386845964821, -0.32665005340726871, -0.099062965638026412},
        {-0.5351013673483962, -1.295318960230734, -1.5990709378824448},
        {1.0720217834317047, 0.71993606440402225, 0.23645028373967136},
        {-0.99279068651465252, -0.98643410334887527, -0.73294549091379935},
        {0.076958030427935142, 0.36600365041898719, 0.49189606878540815},
        {0.49521653879377325, -0.0068845891759305999, -0.36220054332208207},
        {0.62848282800965549, 1.1516244187529558, 1.0953174499901195},
        {2.0367508301936965, 1.0857175933216947, 0.011288908064983616},
        {-1.3878543145390587, 0.4441991140076329, 1.6114767808642583},
        {1.522594440755487, 0.33763549323542463, -0.67705500450833966},
        {-0.35515982194690565, 0.7823974532528748, 1.3596714723854717},
    };
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    rvd.compute(seeds, options, result);
    // The configuration: sample 8 has two pieces, one of them in just the two triangles.
    int lens = -1;
    for (size_t p = 0; p < result.pieceSeed.size(); ++p) {
        if (result.pieceSeed[p] != 8) continue;
        int faces = 0;
        for (const auto& t : result.pieceTriangles) faces += std::count(t.begin(), t.end(), static_cast<int>(p));
        if (faces == 2) lens = static_cast<int>(p);
    }
    ASSERT_GE(lens, 0) << "the lens piece of sample 8";

    ClosestPointTree tree(surface);
    const RdtResult rdt = extractRdt(seeds, result, tree);
    EXPECT_EQ(rdt.removedFaces, 0);
    EXPECT_EQ(rdt.lensPieces, 1);
    EXPECT_EQ(rdt.splitVertices, 0);
    EXPECT_TRUE(computeTopology(rdt.mesh).manifold());
    // Edge (12, 13) has two faces, (8, 13, 12) and (10, 12, 13), in opposite directions.
    std::vector<int> third;
    for (const Face& f : rdt.mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = rdt.seedOfVertex[f[k]], b = rdt.seedOfVertex[f[(k + 1) % 3]];
            if ((a == 12 && b == 13) || (a == 13 && b == 12))
                third.push_back(rdt.seedOfVertex[f[(k + 2) % 3]] * (a == 12 ? 1 : -1));
        }
    std::sort(third.begin(), third.end());
    EXPECT_EQ(third, (std::vector<int>{-8, 10}));
}

TEST(Rdt, PillowAloneIsKept)
{
    // Three samples on a closed surface: the RDT is one triangle with both orientations. Its
    // vertices have degree 2 but nothing else is on its edges: it stays (it is the surface).
    const std::vector<Vec3> seeds = {{1, 0, 0}, {-0.5, 0.8, 0}, {-0.5, -0.8, 0}};
    TriMesh surface;
    surface.vertices = {{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}};
    surface.faces = {{0, 1, 2}};
    ClosestPointTree tree(surface);
    const RdtResult r = extractRdt(seeds, {{0, 1, 2}, {0, 2, 1}}, tree);
    EXPECT_EQ(r.lensPieces, 0);
    EXPECT_EQ(r.removedFaces, 0);
    EXPECT_EQ(r.mesh.faceCount(), 2);
}

TEST(Rdt, PillowOnAnEdgeWithOtherFacesIsDropped)
{
    // A fan of four faces around candidate 0 (a disk) and a pillow of candidate 5 on its edge
    // (0, 1): without the lens rule, edge (0, 1) has four faces and all are removed.
    const std::vector<Vec3> seeds = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0.5, 0, 0}};
    TriMesh surface;
    surface.vertices = {{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}};
    surface.faces = {{0, 1, 2}};
    ClosestPointTree tree(surface);
    const RdtResult r = extractRdt(seeds, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {5, 0, 1}, {5, 1, 0}}, tree);
    EXPECT_EQ(r.lensPieces, 1);
    EXPECT_EQ(r.removedFaces, 0);
    EXPECT_EQ(r.mesh.faceCount(), 4);
    EXPECT_EQ(r.droppedSeeds, 1);  // candidate 5 was only the lens
    EXPECT_TRUE(computeTopology(r.mesh).manifold());
}

// Each output vertex knows the input face it lies on (a hint for the valence stage's queries);
// hints for the seeds' queries change nothing but the speed.
TEST(Rdt, VerticesKnowTheirFaceAndHintsChangeNothing)
{
    const TriMesh surface = testmesh::torus(40, 20);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 300, 3);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    rvd.compute(seeds, options, result);
    ClosestPointTree tree(surface);
    const RdtResult plain = extractRdt(seeds, result, tree);
    ASSERT_EQ(plain.faceOfVertex.size(), plain.mesh.vertices.size());
    for (size_t v = 0; v < plain.mesh.vertices.size(); ++v) {
        const int f = plain.faceOfVertex[v];
        ASSERT_GE(f, 0);
        const Face& t = surface.faces[f];
        const Vec3 a = surface.vertices[t[0]], b = surface.vertices[t[1]], c = surface.vertices[t[2]];
        const Vec3 p = plain.mesh.vertices[v];
        // On the face's plane and inside it (barycentric coordinates >= 0, up to rounding).
        const Vec3 n = (b - a).cross(c - a);
        EXPECT_NEAR(n.normalized().dot(p - a), 0.0, 1e-12);
        EXPECT_GE((b - a).cross(p - a).dot(n), -1e-12 * n.squaredNorm());
        EXPECT_GE((c - b).cross(p - b).dot(n), -1e-12 * n.squaredNorm());
        EXPECT_GE((a - c).cross(p - c).dot(n), -1e-12 * n.squaredNorm());
    }
    // Hints far off (every seed pointed at face 0) and near (the faces found): the same mesh.
    const RdtResult far = extractRdt(seeds, result, tree, std::vector<int>(seeds.size(), 0));
    std::vector<int> near(seeds.size(), -1);
    for (size_t v = 0; v < plain.seedOfVertex.size(); ++v) near[plain.seedOfVertex[v]] = plain.faceOfVertex[v];
    const RdtResult hinted = extractRdt(seeds, result, tree, near);
    EXPECT_EQ(far.mesh.vertices, plain.mesh.vertices);
    EXPECT_EQ(hinted.mesh.vertices, plain.mesh.vertices);
    EXPECT_EQ(hinted.mesh.faces, plain.mesh.faces);
    EXPECT_THROW(extractRdt(seeds, result, tree, std::vector<int>(3, 0)), InvalidInputError);
}

// Debris (issue 32 item 3): a crumb of a few faces beside the rest of the output is dropped with
// its vertices (their samples and face hints with them); one as small but far from the rest (a
// small part of the input of its own) is kept.
TEST(Rdt, DebrisBesideTheRestIsDroppedAndFarPiecesKept)
{
    RdtResult rdt;
    rdt.mesh = testmesh::planeGrid(6);  // 49 vertices, 72 faces, edges 1/6
    auto crumb = [&](const Vec3& at) {
        const int base = rdt.mesh.vertexCount();
        for (const Vec3& d : {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0)}) rdt.mesh.vertices.push_back(at + d);
        rdt.mesh.faces.push_back({base, base + 1, base + 2});
    };
    crumb(Vec3(0.5, 0.5, 0.1));  // 0.1 above the grid
    crumb(Vec3(0.5, 0.5, 3.0));  // far above it
    for (int v = 0; v < rdt.mesh.vertexCount(); ++v) {
        rdt.seedOfVertex.push_back(1000 + v);
        rdt.faceOfVertex.push_back(2000 + v);
    }
    EXPECT_EQ(dropDebris(rdt, 4, 0.3), 1);
    EXPECT_EQ(rdt.debrisPieces, 1);
    ASSERT_EQ(rdt.mesh.vertexCount(), 52);
    ASSERT_EQ(rdt.mesh.faceCount(), 73);
    ASSERT_EQ(rdt.seedOfVertex.size(), 52u);
    ASSERT_EQ(rdt.faceOfVertex.size(), 52u);
    // The far crumb's vertices keep their samples and hints: they were vertices 52-54.
    const Face& far = rdt.mesh.faces.back();
    EXPECT_NEAR(rdt.mesh.vertices[far[0]].z(), 3.0, 1e-12);
    EXPECT_EQ(rdt.seedOfVertex[far[0]], 1000 + 52);
    EXPECT_EQ(rdt.faceOfVertex[far[2]], 2000 + 54);
    EXPECT_EQ(rdt.warnings.size(), 1u);
    // Nothing left to drop: the same mesh again.
    EXPECT_EQ(dropDebris(rdt, 4, 0.3), 0);
    EXPECT_EQ(rdt.mesh.faceCount(), 73);
}
