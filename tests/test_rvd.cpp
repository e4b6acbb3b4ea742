// The exact restricted Voronoi diagram: invariants and a case with a known answer.
#include "boundary.h"
#include "rvd.h"
#include "sampling.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include <numeric>

using namespace fieldcvt;

namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

TEST(Rvd, CellAreasSumToSurfaceArea)
{
    for (const TriMesh& surface : {testmesh::icosphere(3), testmesh::torus(40, 20), testmesh::planeGrid(12)}) {
        for (int count : {1, 7, 300}) {
            const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, count, 42);
            RestrictedVoronoiDiagram rvd(surface);
            RvdResult result;
            rvd.compute(seeds, RvdOptions{}, result);
            EXPECT_NEAR(sum(result.mass), surfaceArea(surface), 1e-9 * surfaceArea(surface)) << count << " seeds";
            for (double m : result.mass) EXPECT_GE(m, -1e-15);
        }
    }
}

TEST(Rvd, SeedsOffTheSurfaceStillPartitionIt)
{
    // Samples leave the surface during L-BFGS (they move towards off-surface centroids).
    const TriMesh surface = testmesh::icosphere(3);
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 200, 3);
    for (size_t i = 0; i < seeds.size(); ++i) seeds[i] *= (i % 2 ? 0.9 : 1.1);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    rvd.compute(seeds, RvdOptions{}, result);
    EXPECT_NEAR(sum(result.mass), surfaceArea(surface), 1e-9 * surfaceArea(surface));
}

TEST(Rvd, OneSeedHasTheWholeSurfaceAndNoEdge)
{
    // No edge at all: the edge merge must not step off its (empty) buffer (a fuzzer's finding,
    // caught by UBSan in the sanitizer step).
    const TriMesh surface = testmesh::icosphere(2);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.edges = true;
    rvd.compute({Vec3(0.1, 0.2, 0.3)}, options, result);
    EXPECT_TRUE(result.edges.empty());
    EXPECT_NEAR(result.mass[0], surfaceArea(surface), 1e-9 * surfaceArea(surface));
}

TEST(Rvd, SquareLatticeOnAPlaneGivesSquareCells)
{
    // Seeds at the centres of a k x k grid on the unit square: every cell is the grid square,
    // with mass h², centroid at the seed, energy h⁴/6, and shared edges of length h.
    const int k = 5;
    const double h = 1.0 / k;
    const TriMesh surface = testmesh::planeGrid(7);  // triangle edges do not follow the cells
    std::vector<Vec3> seeds;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) seeds.emplace_back((i + 0.5) * h, (j + 0.5) * h, 0.0);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.edges = true;
    rvd.compute(seeds, options, result);
    for (size_t s = 0; s < seeds.size(); ++s) {
        EXPECT_NEAR(result.mass[s], h * h, 1e-12);
        EXPECT_NEAR((result.moment[s] / result.mass[s] - seeds[s]).norm(), 0.0, 1e-12);
        EXPECT_NEAR(result.energy[s], h * h * h * h / 6.0, 1e-12);
    }
    int axisNeighbours = 0;
    for (const RvdEdge& e : result.edges) {
        const Vec3 d = seeds[e.j] - seeds[e.i];
        if (std::abs(d.norm() - h) < 1e-12) {
            ++axisNeighbours;
            EXPECT_NEAR(e.length, h, 1e-12);
        } else {
            EXPECT_NEAR(e.length, 0.0, 1e-12);  // diagonal pairs touch at a corner at most
        }
    }
    EXPECT_EQ(axisNeighbours, 2 * k * (k - 1));
}

TEST(Rvd, HexagonalLatticeGivesEquilateralDelaunayTriangles)
{
    // A triangular lattice of seeds: every interior RDT triangle is equilateral.
    const double h = 0.1;
    const TriMesh surface = testmesh::planeGrid(9, 1.0);
    std::vector<Vec3> seeds;
    for (int j = 0; j * h * std::sqrt(3.0) / 2 <= 1.0; ++j)
        for (int i = 0; (i + 0.5 * (j % 2)) * h <= 1.0; ++i)
            seeds.emplace_back((i + 0.5 * (j % 2)) * h, j * h * std::sqrt(3.0) / 2, 0.0);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    rvd.compute(seeds, options, result);
    ASSERT_GT(result.triangles.size(), 100u);
    for (const auto& t : result.triangles) {
        const Vec3 a = seeds[t[0]], b = seeds[t[1]], c = seeds[t[2]];
        EXPECT_NEAR((b - a).norm(), h, 1e-9);
        EXPECT_NEAR((c - b).norm(), h, 1e-9);
        EXPECT_NEAR((a - c).norm(), h, 1e-9);
        EXPECT_GT((b - a).cross(c - a).z(), 0.0) << "oriented like the input (normal +z)";
    }
}

TEST(Rvd, CoincidentSeedsAreNotCountedTwice)
{
    const TriMesh surface = testmesh::icosphere(2);
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 50, 9);
    seeds.push_back(seeds[10]);
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult result;
    rvd.compute(seeds, RvdOptions{}, result);
    EXPECT_NEAR(sum(result.mass), surfaceArea(surface), 1e-9 * surfaceArea(surface));
    EXPECT_EQ(result.mass.back(), 0.0);
}

TEST(Rvd, BorderLengthsFromTheBorderFacesAloneAreTheWholeDiagrams)
{
    // The border's 1D cells partition the border (their lengths sum to its length), and the
    // border-faces-only diagram (the border relaxation's) gives them bit for bit, while its
    // masses cover only the border faces.
    const TriMesh surface = testmesh::disk(12);
    double borderLength = 0;
    for (const Segment& s : boundarySegments(surface)) borderLength += (s.second - s.first).norm();
    ASSERT_GT(borderLength, 0);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 120, 4);
    RestrictedVoronoiDiagram rvd(surface);
    RvdOptions options;
    options.boundary = true;
    RvdResult whole, border;
    rvd.compute(seeds, options, whole);
    options.borderFacesOnly = true;
    rvd.compute(seeds, options, border);
    EXPECT_NEAR(sum(whole.boundaryLength), borderLength, 1e-9 * borderLength);
    EXPECT_EQ(border.boundaryLength, whole.boundaryLength);
    ASSERT_EQ(border.boundaryMoment.size(), whole.boundaryMoment.size());
    for (size_t i = 0; i < seeds.size(); ++i) EXPECT_EQ(border.boundaryMoment[i], whole.boundaryMoment[i]) << i;
    EXPECT_GT(sum(border.mass), 0.0);
    EXPECT_LT(sum(border.mass), 0.5 * sum(whole.mass));
}

TEST(Rvd, ResultDoesNotDependOnThreadCount)
{
    const TriMesh surface = testmesh::torus(60, 30);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 500, 5);
    RestrictedVoronoiDiagram rvd(surface);
    RvdOptions options;
    options.edges = options.triangles = true;
    RvdResult one, two;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    rvd.compute(seeds, options, one);
    omp_set_num_threads(2);
    rvd.compute(seeds, options, two);
    omp_set_num_threads(threads);
    EXPECT_EQ(one.mass, two.mass);
    EXPECT_EQ(one.energy, two.energy);
    EXPECT_EQ(one.triangles, two.triangles);
    ASSERT_EQ(one.edges.size(), two.edges.size());
    for (size_t e = 0; e < one.edges.size(); ++e) EXPECT_EQ(one.edges[e].length, two.edges[e].length);
}

//! Two diagrams equal bit for bit: masses, energies, triangles (on pieces too), edge lengths.
void expectSameDiagram(const RvdResult& a, const RvdResult& b)
{
    EXPECT_EQ(a.mass, b.mass);
    EXPECT_EQ(a.energy, b.energy);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.pieceTriangles, b.pieceTriangles);
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t e = 0; e < a.edges.size(); ++e) EXPECT_EQ(a.edges[e].length, b.edges[e].length);
}

TEST(Rvd, WarmStartedNeighbourSearchGivesTheSameDiagram)
{
    // compute() bounds its nearest-seed search by the previous call's neighbour lists; after a
    // call on other seeds the diagram must equal the one of a fresh object, bit for bit.
    const TriMesh surface = testmesh::torus(60, 30);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 400, 8);
    std::vector<Vec3> moved = seeds;
    for (size_t i = 0; i < moved.size(); ++i) moved[i] += 0.02 * Vec3(std::sin(1.0 * i), std::cos(3.0 * i), std::sin(7.0 * i));
    RvdOptions options;
    options.edges = options.triangles = true;
    RestrictedVoronoiDiagram warm(surface), fresh(surface);
    RvdResult a, b;
    warm.compute(moved, options, a);
    warm.compute(seeds, options, a);
    fresh.compute(seeds, options, b);
    expectSameDiagram(a, b);
}

TEST(Rvd, ReleasedWorkspaceGivesTheSameDiagramAgain)
{
    // releaseWorkspace() frees what compute() keeps between calls; the next call allocates it
    // again and must give the same diagram, pieces and triangles included.
    const TriMesh surface = testmesh::torus(60, 30);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 400, 8);
    RvdOptions options;
    options.edges = options.triangles = true;
    RestrictedVoronoiDiagram rvd(surface);
    RvdResult before, after;
    rvd.compute(seeds, options, before);
    rvd.releaseWorkspace();
    rvd.compute(seeds, options, after);
    expectSameDiagram(before, after);
}

TEST(Rvd, EachNeighbourClipsAPolygonOnce)
{
    // Seeds on a short segment in one corner of a plane of two triangles: every cell is a strip
    // across the plane, so no polygon's security radius is reached before all the other seeds
    // (the stored neighbours, then the candidates, then the k-d tree in growing rounds) have
    // clipped it. Each must clip it once: n - 1 clips per (cell, triangle), whatever the rounds
    // (they used to repeat the seeds of the earlier round: 12 + 37 + 47 for n = 60).
    const TriMesh plane = testmesh::planeGrid(1);
    std::vector<Vec3> seeds;
    for (int i = 0; i < 60; ++i) seeds.emplace_back(0.001 * i, 0.0004 * i + 0.001, 0.0);
    const long long n = static_cast<long long>(seeds.size());
    RestrictedVoronoiDiagram diagram(plane);
    RvdResult result;
    diagram.compute(seeds, RvdOptions{}, result);
    double area = 0;
    for (double m : result.mass) area += m;
    EXPECT_NEAR(area, 1.0, 1e-12);
    EXPECT_LE(result.clippedPolygons, 2 * n * (n - 1));
    EXPECT_GE(result.clippedPolygons, n * (n - 1));  // every cell meets a triangle: the strips are clipped fully
}

TEST(Rvd, NeighbourListsFromCandidatesGiveTheSameDiagram)
{
    // compute() takes most neighbour lists from the candidate lists of an earlier call while the
    // seeds move little (L-BFGS steps). Along a path of small steps, with one seed jumping far
    // and one landing on another, every diagram must equal a fresh object's, bit for bit. The far
    // jump does not invalidate the other lists: the jumping seed is a "mover", checked against
    // every list, so the seeds near where it lands take theirs from the k-d tree and the rest
    // keep their candidates.
    const TriMesh surface = testmesh::torus(60, 30);
    const std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 400, 8);
    RvdOptions options;
    options.edges = options.triangles = true;
    RestrictedVoronoiDiagram warm(surface);
    int fromCandidates = 0;
    std::vector<Vec3> current = seeds;
    for (int step = 0; step < 12; ++step) {
        for (size_t i = 0; i < current.size(); ++i)
            current[i] += 0.01 * Vec3(std::sin(1.0 * i + step), std::cos(3.0 * i - step), std::sin(7.0 * i * step));
        if (step == 5) current[17] = current[200] + Vec3(0.5, 0, 0);  // a far jump
        if (step == 8) current[33] = current[34];                     // coincident seeds
        RvdResult a, b;
        warm.compute(current, options, a);
        RestrictedVoronoiDiagram fresh(surface);
        fresh.compute(current, options, b);
        fromCandidates += a.listsFromCandidates;
        EXPECT_EQ(b.listsFromCandidates, 0);
        if (step == 5) EXPECT_GT(a.listsFromCandidates, 300);
        EXPECT_EQ(a.mass, b.mass) << "step " << step;
        EXPECT_EQ(a.moment, b.moment) << "step " << step;
        EXPECT_EQ(a.energy, b.energy) << "step " << step;
        EXPECT_EQ(a.triangles, b.triangles) << "step " << step;
        EXPECT_EQ(a.pieceTriangles, b.pieceTriangles) << "step " << step;
        ASSERT_EQ(a.edges.size(), b.edges.size());
        for (size_t e = 0; e < a.edges.size(); ++e) EXPECT_EQ(a.edges[e].length, b.edges[e].length);
    }
    // The path exercises the candidate lists (most seeds, most steps), not only the k-d tree.
    EXPECT_GT(fromCandidates, 6 * 400);
}
