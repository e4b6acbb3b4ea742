// The field-aligned lattice start (core/lattice.h): lattice rounding, agreement of neighbouring
// lattices after the multi-resolution smoothing, the count and spacing of the samples, and the
// issue-13 cylinder run whose interior is all valence 6.
#include "field_hierarchy.h"
#include "lattice.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "remesh.h"
#include "test_meshes.h"
#include "working_frame.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace fieldcvt;

namespace {

TriMesh workingCopy(const std::string& name, int count)
{
    InputReport report;
    TriMesh m = prepareInput(readMesh(testmesh::resource(name)), report);
    const Normalisation frame = workingFrame(m, count);
    for (Vec3& p : m.vertices) p = frame.toWork(p);
    return m;
}

// The lattice's two generators from d: ρ·d and ρ·R60·d.
void generators(const Vec3& d, const Vec3& n, double rho, Vec3& g1, Vec3& g2)
{
    g1 = rho * d;
    g2 = rho * (0.5 * d + rosy::kSin60 * n.cross(d));
}

// Distance from the lattice of edge (i, j)'s first end to the second end's, compared near the
// edge's middle point, in lattice steps (0 when the two lattices are the same there).
double edgeMismatch(const TriMesh& m, const DirectionField& f, const std::vector<Vec3>& origin, double rho, int i, int j)
{
    const Vec3 middle = middlePoint(m.vertices[i], f.normals[i], m.vertices[j], f.normals[j]);
    const Vec3 a = nearestLatticePoint(origin[i], f.directions[i], f.normals[i], rho, middle);
    const Vec3 b = nearestLatticePoint(origin[j], f.directions[j], f.normals[j], rho, a);
    return (a - b).norm() / rho;
}

}  // namespace

TEST(Lattice, NearestLatticePointIsTheNearestOfItsLattice)
{
    // Against a brute-force search over integer coordinates, for random origins, frames and targets.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int trial = 0; trial < 500; ++trial) {
        const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
        const Vec3 d = rosy::projectTangent(Vec3(u(rng), u(rng), u(rng)), n).normalized();
        const Vec3 origin(u(rng), u(rng), u(rng));
        const Vec3 target = origin + Vec3(u(rng), u(rng), u(rng));
        const double rho = 0.3 + 0.1 * (trial % 7);
        const Vec3 q = nearestLatticePoint(origin, d, n, rho, target);
        Vec3 g1, g2;
        generators(d, n, rho, g1, g2);
        const Vec3 planar = target - n.dot(target - origin) * n;
        double best = std::numeric_limits<double>::infinity();
        for (int a = -40; a <= 40; ++a)
            for (int b = -40; b <= 40; ++b) best = std::min(best, (origin + a * g1 + b * g2 - planar).norm());
        EXPECT_NEAR((q - planar).norm(), best, 1e-9);
        // q is a lattice point: integer coordinates in (g1, g2).
        const Vec3 r = q - origin;
        const double v = r.dot(n.cross(d)) / (rosy::kSin60 * rho), w = r.dot(d) / rho - 0.5 * v;
        EXPECT_NEAR(v, std::round(v), 1e-9);
        EXPECT_NEAR(w, std::round(w), 1e-9);
    }
}

TEST(Lattice, TheSixFieldDirectionsGiveTheSameLattice)
{
    // Invariance to the representative: d and R60·d (and −d) span one lattice.
    const Vec3 n = Vec3(0.2, -0.3, 0.9).normalized();
    const Vec3 d = rosy::anyTangent(n);
    Vec3 reps[3];
    rosy::representatives3(d, n, reps);
    const Vec3 origin(0.1, 0.2, 0.3);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-4, 4);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 target = origin + rosy::projectTangent(Vec3(u(rng), u(rng), u(rng)), n);
        const Vec3 q = nearestLatticePoint(origin, d, n, 1.0, target);
        for (const Vec3& r : reps) {
            EXPECT_LT((nearestLatticePoint(origin, r, n, 1.0, target) - q).norm(), 1e-9);
            EXPECT_LT((nearestLatticePoint(origin, -r, n, 1.0, target) - q).norm(), 1e-9);
        }
    }
}

TEST(Lattice, MiddlePointLiesOnBothTangentPlanes)
{
    const Vec3 p0(0, 0, 0), p1(1, 0.2, 0.1);
    const Vec3 n0 = Vec3(0, 0.1, 1).normalized(), n1 = Vec3(0.3, -0.1, 1).normalized();
    const Vec3 m = middlePoint(p0, n0, p1, n1);
    EXPECT_NEAR(n0.dot(m - p0), 0, 1e-3);  // the regulariser leaves a small residual
    EXPECT_NEAR(n1.dot(m - p1), 0, 1e-3);
    // ... and is the nearest such point to the midpoint: it moved along the normals only.
    EXPECT_NEAR((m - 0.5 * (p0 + p1)).dot(n0.cross(n1).normalized()), 0, 1e-12);
}

TEST(Lattice, CylinderLatticesAgreeEverywhere)
{
    // The cylinder's field has no singularity: after the multi-resolution smoothing every
    // vertex's lattice is its neighbours' (a random or a single-level start leaves mismatches).
    const TriMesh m = workingCopy("cylinder.off", 1000);
    const DirectionField f = computeField(m, FieldParams{});
    const double rho = latticeSpacingFor(m, 1000);
    const std::vector<Vec3> origin = solvePositionField(m, f, rho, LatticeParams{}.iterations);
    double worst = 0;
    for (const Face& t : m.faces)
        for (int k = 0; k < 3; ++k) worst = std::max(worst, edgeMismatch(m, f, origin, rho, t[k], t[(k + 1) % 3]));
    EXPECT_LT(worst, 0.2);
    // Each origin is its lattice's point nearest to its vertex.
    for (int v = 0; v < m.vertexCount(); ++v) EXPECT_LT((origin[v] - m.vertices[v]).norm(), 0.6 * rho);
}

TEST(Lattice, FewMismatchesAwayFromSingularitiesOnFertility)
{
    // Genus 4: the field has singularities, where lattices cannot agree; elsewhere they do.
    const TriMesh m = workingCopy("fertility.off", 3000);
    const DirectionField f = computeField(m, FieldParams{});
    const double rho = latticeSpacingFor(m, 3000);
    const std::vector<Vec3> origin = solvePositionField(m, f, rho, LatticeParams{}.iterations);
    int mismatched = 0, edges = 0;
    for (const Face& t : m.faces)
        for (int k = 0; k < 3; ++k, ++edges) mismatched += edgeMismatch(m, f, origin, rho, t[k], t[(k + 1) % 3]) > 0.25;
    std::printf("fertility 3000: %d of %d edge sides see another lattice\n", mismatched, edges);
    EXPECT_LT(mismatched, 0.08 * edges);  // measured 4.2 %
}

TEST(Lattice, SamplesHaveTheCountAndTheSpacing)
{
    for (const auto& [name, count] : std::vector<std::pair<std::string, int>>{{"cylinder.off", 1000}, {"fertility.off", 3000}}) {
        const TriMesh m = workingCopy(name, count);
        const DirectionField f = computeField(m, FieldParams{});
        LatticeReport report;
        const std::vector<Vec3> samples = latticeSamples(m, f, count, LatticeParams{}, &report);
        EXPECT_EQ(report.samples, static_cast<int>(samples.size()));
        EXPECT_NEAR(double(samples.size()), count, 0.03 * count) << name;
        EXPECT_GE(report.passes, 1);
        EXPECT_LE(report.passes, LatticeParams{}.maxPasses);
        EXPECT_GT(report.candidates, report.samples);  // each point comes from several face corners
        // Nearest-neighbour distances: the lattice step almost everywhere (merged copies
        // would be ~0 apart, gaps ~1.7 steps).
        int nearStep = 0, close = 0;
        for (size_t i = 0; i < samples.size(); ++i) {
            double nearest = std::numeric_limits<double>::infinity();
            for (size_t j = 0; j < samples.size(); ++j)
                if (j != i) nearest = std::min(nearest, (samples[i] - samples[j]).norm());
            close += nearest < 0.5 * report.spacing;
            nearStep += std::abs(nearest / report.spacing - 1) < 0.1;
        }
        std::printf("%s: %zu samples, %.1f %% with the nearest one a lattice step away, %d closer than half a step\n",
                    name.c_str(), samples.size(), 100.0 * nearStep / samples.size(), close);
        // Where lattices disagree (singularities) two points can survive closer than the merge
        // radius of each other's first copy; measured: cylinder 0, fertility 64 of 2997 (seed 1).
        EXPECT_LE(close, (name == "cylinder.off" ? 0 : 0.03) * samples.size()) << name;
        // Measured: cylinder 100 %, fertility 73 % (curved: 3D distances between points of
        // tangent-plane lattices are shorter than their step; and the singularities).
        EXPECT_GT(nearStep, (name == "cylinder.off" ? 0.97 : 0.65) * samples.size()) << name;
    }
}

TEST(Lattice, SamplesDoNotDependOnTheThreadCount)
{
    const TriMesh m = workingCopy("fertility.off", 3000);
    const DirectionField f = computeField(m, FieldParams{});
    const int previous = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::vector<Vec3> one = latticeSamples(m, f, 3000, LatticeParams{});
    omp_set_num_threads(2);
    const std::vector<Vec3> two = latticeSamples(m, f, 3000, LatticeParams{});
    omp_set_num_threads(previous);
    ASSERT_EQ(one.size(), two.size());
    for (size_t i = 0; i < one.size(); ++i) EXPECT_EQ(one[i], two[i]);
}

// Each point names a face it came from: within a spacing of it (the hint of its closest-point
// query in the pipeline).
TEST(Lattice, SamplesNameAFaceTheyCameFrom)
{
    const TriMesh m = workingCopy("fertility.off", 3000);
    const DirectionField f = computeField(m, FieldParams{});
    std::vector<int> faces;
    LatticeReport report;
    const std::vector<Vec3> samples = latticeSamples(m, f, 3000, LatticeParams{}, &report, nullptr, &faces);
    ASSERT_EQ(faces.size(), samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
        ASSERT_GE(faces[i], 0);
        ASSERT_LT(faces[i], m.faceCount());
        const Face& t = m.faces[faces[i]];
        const Vec3 centroid = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
        double size = 0;
        for (int k = 0; k < 3; ++k) size = std::max(size, (m.vertices[t[k]] - centroid).norm());
        EXPECT_LT((samples[i] - centroid).norm(), size + report.spacing) << "sample " << i;
    }
}

TEST(Lattice, CylinderInteriorIsAllValenceSix)
{
    // Issue 13, item 2: cylinder.off at 1000 vertices, default pipeline: every interior vertex
    // of valence 6 (a random start kept 11 pairs of 5 and 7), both rims with the same count.
    // With --random-start the pairs come back (the start, not the rest, makes the difference).
    const TriMesh input = readMesh(testmesh::resource("cylinder.off"));
    for (bool lattice : {true, false}) {
        RemeshParams params;
        params.vertexCount = 1000;
        params.latticeStart = lattice;
        params.computeDistances = false;
        const RemeshResult r = remesh(input, params);
        std::map<std::pair<int, int>, int> edges;
        for (const Face& f : r.mesh.faces)
            for (int k = 0; k < 3; ++k) ++edges[std::minmax(f[k], f[(k + 1) % 3])];
        std::vector<int> valence(r.mesh.vertexCount(), 0);
        std::set<int> border;
        for (const auto& [e, count] : edges) {
            ++valence[e.first], ++valence[e.second];
            if (count == 1) border.insert(e.first), border.insert(e.second);
        }
        int irregular = 0, top = 0, bottom = 0;
        for (int v = 0; v < r.mesh.vertexCount(); ++v) {
            if (border.count(v))
                (r.mesh.vertices[v].z() > 0 ? top : bottom)++;
            else
                irregular += valence[v] != 6;
        }
        std::printf("cylinder 1000, %s start: %d vertices, %d irregular interior, rims %d / %d\n", lattice ? "lattice" : "random",
                    r.mesh.vertexCount(), irregular, top, bottom);
        if (lattice) {
            EXPECT_EQ(irregular, 0);
            EXPECT_EQ(top, bottom);
            EXPECT_EQ(r.lattice.passes > 0, true);
            EXPECT_NEAR(r.mesh.vertexCount(), 1000, 30);
            EXPECT_EQ(r.metrics.v6Pct, 100.0);
        } else {
            EXPECT_GT(irregular, 0);
            EXPECT_EQ(r.lattice.passes, 0);
        }
    }
}
