// Side-aware restricted Voronoi cells (RvdOptions::seedNormals): on a plate thinner than the
// cells, a seed owns nothing of the far side, and the seam triangles along the creases where the
// owners change close the restricted Delaunay triangulation.
#include "metrics.h"
#include "rvd.h"
#include "sampling.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numeric>

using namespace fieldcvt;

namespace {

constexpr double kThickness = 0.02;

//! Seeds on both sides of testmesh::thinBox: a k x k grid on top (normal +y) and one shifted by
//! a fraction of a cell on the bottom (normal -y), so that plain cells of top seeds reach the
//! bottom between the bottom seeds.
struct PlateSeeds {
    std::vector<Vec3> points, normals;
    int top = 0;  //!< the first `top` seeds are the top ones
};

PlateSeeds plateSeeds(int k)
{
    PlateSeeds seeds;
    for (int side = 0; side < 2; ++side)
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                // Shifted, and jittered a little: no two seeds at exactly the same distance from a
                // third (the clipping order of equidistant neighbours is not specified).
                const double shift = side == 0 ? 0.5 : 0.15;
                const double jitter = 0.05 * std::sin(12.9898 * (i + 31 * j + 977 * side));
                seeds.points.emplace_back((i + shift + jitter) / k, side == 0 ? kThickness : 0.0, (j + 0.7 * shift - jitter) / k);
                seeds.normals.emplace_back(0, side == 0 ? 1 : -1, 0);
            }
    seeds.top = k * k;
    return seeds;
}

double topMass(const RvdResult& result, int top) { return std::accumulate(result.mass.begin(), result.mass.begin() + top, 0.0); }

TriMesh delaunayMesh(const std::vector<Vec3>& seeds, const RvdResult& result)
{
    TriMesh mesh;
    mesh.vertices = seeds;
    for (const auto& t : result.triangles) mesh.faces.push_back({t[0], t[1], t[2]});
    return mesh;
}

}  // namespace

TEST(RvdSides, CellsKeepToTheirSideOfAThinPlate)
{
    const TriMesh plate = testmesh::thinBox(12, kThickness);
    const PlateSeeds seeds = plateSeeds(6);
    RestrictedVoronoiDiagram rvd(plate);
    RvdResult plain, sided;
    rvd.compute(seeds.points, RvdOptions{}, plain);
    RvdOptions options;
    options.seedNormals = &seeds.normals;
    rvd.compute(seeds.points, options, sided);
    const double area = surfaceArea(plate), rim = 4 * kThickness;
    // Both partition the surface.
    EXPECT_NEAR(std::accumulate(plain.mass.begin(), plain.mass.end(), 0.0), area, 1e-9 * area);
    EXPECT_NEAR(std::accumulate(sided.mass.begin(), sided.mass.end(), 0.0), area, 1e-9 * area);
    // Plain cells of the top seeds take much of the bottom; side-aware ones the top and at most
    // the rim.
    EXPECT_GT(topMass(plain, seeds.top), 1.0 + rim + 0.05);
    EXPECT_GE(topMass(sided, seeds.top), 1.0 - 1e-9);
    EXPECT_LE(topMass(sided, seeds.top), 1.0 + rim + 1e-9);
}

TEST(RvdSides, SeamTrianglesCloseTheDelaunayTriangulationOfAThinPlate)
{
    const TriMesh plate = testmesh::thinBox(12, kThickness);
    const PlateSeeds seeds = plateSeeds(6);
    RestrictedVoronoiDiagram rvd(plate);
    RvdOptions options;
    options.triangles = true;
    options.seedNormals = &seeds.normals;
    RvdResult sided;
    rvd.compute(seeds.points, options, sided);
    const TopologySummary topology = computeTopology(delaunayMesh(seeds.points, sided));
    EXPECT_TRUE(topology.manifold());
    EXPECT_EQ(topology.boundaryLoops, 0);
    EXPECT_EQ(topology.components, 1);
    EXPECT_EQ(topology.genus, 0);
    // Each top seed has a triangle with top seeds only, and none with three bottom ones: the
    // two sides are separate sheets joined along the rim.
    int mixed = 0;
    for (const auto& t : sided.triangles) {
        const int onTop = (t[0] < seeds.top) + (t[1] < seeds.top) + (t[2] < seeds.top);
        mixed += onTop == 1 || onTop == 2;
    }
    EXPECT_GT(mixed, 0);
    EXPECT_LT(mixed, static_cast<int>(sided.triangles.size()) / 2);
}

TEST(RvdSides, NormalsThatExcludeNoSeedChangeNothing)
{
    const TriMesh surface = testmesh::planeGrid(20);  // every face's normal is +z
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 150, 7);
    const std::vector<Vec3> normals(seeds.size(), Vec3(0, 0, 1));
    RestrictedVoronoiDiagram rvd(surface);
    RvdOptions options;
    options.triangles = options.edges = true;
    RvdResult plain, sided;
    rvd.compute(seeds, options, plain);
    options.seedNormals = &normals;
    rvd.compute(seeds, options, sided);
    EXPECT_EQ(plain.mass, sided.mass);
    EXPECT_EQ(plain.energy, sided.energy);
    EXPECT_EQ(plain.triangles, sided.triangles);
    EXPECT_EQ(plain.pieceTriangles, sided.pieceTriangles);
}

TEST(RvdSides, ResultDoesNotDependOnThreadCount)
{
    const TriMesh plate = testmesh::thinBox(24, kThickness);
    const PlateSeeds seeds = plateSeeds(9);
    RestrictedVoronoiDiagram rvd(plate), again(plate);
    RvdOptions options;
    options.triangles = options.edges = true;
    options.seedNormals = &seeds.normals;
    RvdResult one, two;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    rvd.compute(seeds.points, options, one);
    omp_set_num_threads(2);
    again.compute(seeds.points, options, two);
    omp_set_num_threads(threads);
    EXPECT_EQ(one.mass, two.mass);
    EXPECT_EQ(one.triangles, two.triangles);
    EXPECT_EQ(one.pieceTriangles, two.pieceTriangles);
}
