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

TEST(FieldFrames, HintsFromThePreviousEvaluationGiveTheSameFrames)
{
    // The frames are looked up with the previous closest faces as hints (samples move little
    // between evaluations); the answer must not depend on the hints.
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
    hinted[0] = -1;  // no hint
    hinted[1] = surface.faceCount() - 1;  // a far one
    const FieldFrames withHints = energy.framesAt(points, hinted);
    const FieldFrames without = energy.framesAt(points);
    EXPECT_EQ(withHints.normals, without.normals);
    EXPECT_EQ(withHints.directions, without.directions);
    for (size_t i = 0; i < points.size(); ++i) {
        const ClosestPoint cp = tree.closest(points[i]);
        EXPECT_EQ(hinted[i], cp.face);
        const ClosestPoint withHint = tree.closest(points[i], faces[i]);
        EXPECT_EQ(withHint.face, cp.face);
        EXPECT_EQ(withHint.point, cp.point);
    }
}
