// E_CVT and its gradient (§4.3) against central finite differences.
#include "energy.h"
#include "field.h"
#include "sampling.h"
#include "test_gradient.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <random>

using namespace fieldcvt;

TEST(CvtEnergy, GradientMatchesCentralFiniteDifferences)
{
    const TriMesh surface = testmesh::torus(48, 24);
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 150, 11);
    EnergyFunction energy(surface);
    EXPECT_LT(testgradient::worstRelativeError(energy, flatten(seeds)), 1e-5);
}

TEST(CvtEnergy, GradientVanishesAtALatticeCvt)
{
    // Seeds at the centres of a square grid on a plane are a CVT: zero gradient.
    const TriMesh surface = testmesh::planeGrid(4);
    std::vector<Vec3> seeds;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) seeds.emplace_back((i + 0.5) / 4, (j + 0.5) / 4, 0.0);
    EnergyFunction energy(surface);
    Eigen::VectorXd gradient;
    energy.evaluate(flatten(seeds), gradient);
    EXPECT_LT(gradient.cwiseAbs().maxCoeff(), 1e-14);
}

TEST(CvtEnergy, DiagramAtReusesTheLastEvaluationOnlyForItsSeeds)
{
    // reseedEmptyCells asks for the masses at the optimiser's result, which is usually the last
    // point evaluated: that diagram is returned, the same figures as a fresh one; other seeds,
    // or a diagram() in between, get a fresh one.
    const TriMesh surface = testmesh::torus(48, 24);
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 150, 11);
    EnergyFunction energy(surface);
    Eigen::VectorXd gradient;
    energy.evaluate(flatten(seeds), gradient);
    const RvdResult& reused = energy.diagramAt(seeds);
    EXPECT_EQ(&reused, &energy.lastDiagram());
    const std::vector<double> masses = reused.mass;
    const std::vector<Vec3> moments = reused.moment;
    EnergyFunction fresh(surface);
    const RvdResult& computed = fresh.diagram(seeds, RvdOptions{});
    EXPECT_EQ(masses, computed.mass);
    EXPECT_EQ(moments, computed.moment);

    std::vector<Vec3> moved = seeds;
    moved[7] += Vec3(0.01, 0.0, 0.0);
    const RvdResult& other = energy.diagramAt(moved);
    EXPECT_EQ(other.mass, fresh.diagram(moved, RvdOptions{}).mass);  // computed for `moved`
    // rvd_ now holds `moved`'s diagram: asking for the evaluated seeds computes theirs again.
    EXPECT_EQ(energy.diagramAt(seeds).mass, masses);
}

TEST(FieldFrames, HintsFromThePreviousEvaluationFollowTheSurface)
{
    // The frames are looked up from the previous answers' faces (samples move little between
    // evaluations) by a walk over the surface: the nearest point around the hint, which is the
    // closest point but where a concave stretch holds another local minimum nearby; without a
    // hint, or with one the walk cannot settle from, the closest point itself.
    const TriMesh surface = testmesh::torus(48, 24);
    DirectionField field = computeField(surface, FieldParams{});
    ClosestPointTree tree(surface);
    EnergyFunction energy(surface);
    energy.setField(&field, &tree, 0.01);
    std::vector<Vec3> points = sampleSurfaceUniform(surface, 300, 3);
    std::vector<int> faces;
    energy.framesAt(points, faces);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> step(-0.05, 0.05);
    for (Vec3& p : points) p += Vec3(step(rng), step(rng), step(rng));
    std::vector<int> hinted = faces;
    hinted[0] = -1;                       // no hint
    hinted[1] = surface.faceCount() - 1;  // a far one: the walk does not get there
    const FieldFrames withHints = energy.framesAt(points, hinted);
    const FieldFrames without = energy.framesAt(points);
    int differ = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const ClosestPoint cp = tree.closest(points[i]);
        if (i < 2) {
            EXPECT_EQ(hinted[i], cp.face) << i;
            EXPECT_EQ(withHints.normals[i], without.normals[i]) << i;
        }
        if (hinted[i] == cp.face) {
            EXPECT_EQ(withHints.normals[i], without.normals[i]) << i;
            EXPECT_EQ(withHints.directions[i], without.directions[i]) << i;
            continue;
        }
        ++differ;
        // A local minimum close to the global one: at most 10 % farther from the point.
        const Face& t = surface.faces[hinted[i]];
        const Vec3 q = closestPointOnTriangle(points[i], surface.vertices[t[0]], surface.vertices[t[1]], surface.vertices[t[2]]);
        EXPECT_LE((q - points[i]).norm(), 1.1 * std::sqrt(cp.squaredDistance)) << i;
    }
    EXPECT_LE(differ, 6);  // of 300 (measured: 3)
    // The tree's answer does not depend on its hint.
    for (size_t i = 0; i < points.size(); ++i) {
        const ClosestPoint withHint = tree.closest(points[i], faces[i]);
        const ClosestPoint cp = tree.closest(points[i]);
        EXPECT_EQ(withHint.face, cp.face);
        EXPECT_EQ(withHint.point, cp.point);
    }
}
