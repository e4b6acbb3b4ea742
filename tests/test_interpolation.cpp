// Interpolation of the 6-RoSy field (paper §4.2).
#include "field.h"
#include "interpolation.h"
#include "field_hierarchy.h"  // rosy:: kernels
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fieldcvt;

namespace {

// Distance between the six-direction sets of (a, n) and (b, n): min over b's rotations.
double setDistance(const Vec3& a, const Vec3& b, const Vec3& n)
{
    double best = 1e300;
    for (int k = 0; k < 6; ++k) best = std::min(best, (a - rotateRepresentative(b, n, k)).norm());
    return best;
}

// A curved mesh with a field whose normals differ between the corners of every face, which is
// where the choice of representatives matters.
DirectionField sphereField(const TriMesh& m, std::uint64_t seed)
{
    FieldParams params;
    params.seed = seed;
    params.smoothingIterations = 2;  // rough on purpose: large angles between neighbours
    return computeField(m, params);
}

}  // namespace

TEST(Interpolation, RotateRepresentative)
{
    const Vec3 n = Vec3(1, 2, 3).normalized();
    const Vec3 d = n.cross(Vec3(0, 0, 1)).normalized();
    for (int k = -7; k <= 7; ++k) {
        const Vec3 r = rotateRepresentative(d, n, k);
        EXPECT_NEAR(r.norm(), 1.0, 1e-14);
        EXPECT_NEAR(r.dot(n), 0.0, 1e-14);
        const double expected = std::cos(k * kPi / 3);
        EXPECT_NEAR(r.dot(d), expected, 1e-14) << k;
        // Counter-clockwise about n: sin of the angle along n × d.
        EXPECT_NEAR(r.dot(n.cross(d)), std::sin(k * kPi / 3), 1e-14) << k;
        EXPECT_LT((r - rotateRepresentative(d, n, k + 6)).norm(), 1e-14);
    }
    EXPECT_EQ(rotateRepresentative(d, n, 0), d);
}

TEST(Interpolation, InvariantToStoredRepresentative)
{
    const TriMesh m = testmesh::icosphere(2);
    const DirectionField field = sphereField(m, 7);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);  // test inputs only
    int checked = 0;
    for (int f = 0; f < m.faceCount(); f += 7) {
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Vec3 bary(a, b, 1 - a - b);
        const FieldSample ref = interpolateField(m, field, f, bary);
        for (int corner = 0; corner < 3; ++corner)
            for (int k = 1; k < 6; ++k) {
                DirectionField rotated = field;
                const int v = m.faces[f][corner];
                rotated.directions[v] = rotateRepresentative(field.directions[v], field.normals[v], k);
                const FieldSample s = interpolateField(m, rotated, f, bary);
                EXPECT_LT((s.normal - ref.normal).norm(), 1e-12);
                EXPECT_LT(setDistance(s.direction, ref.direction, ref.normal), 1e-12)
                    << "face " << f << " corner " << corner << " k " << k;
                ++checked;
            }
    }
    EXPECT_GT(checked, 400);
}

TEST(Interpolation, ResultIsUnitAndTangent)
{
    const TriMesh m = testmesh::icosphere(2);
    const DirectionField field = sphereField(m, 11);
    for (int f = 0; f < m.faceCount(); ++f) {
        const FieldSample s = interpolateField(m, field, f, Vec3(0.2, 0.3, 0.5));
        EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
        EXPECT_NEAR(s.direction.norm(), 1.0, 1e-12);
        EXPECT_NEAR(s.direction.dot(s.normal), 0.0, 1e-12);
    }
}

TEST(Interpolation, ConstantFieldOnPlaneIsReproduced)
{
    const TriMesh m = testmesh::planeGrid(6);
    const Vec3 n(0, 0, 1), d = Vec3(std::cos(0.3), std::sin(0.3), 0);
    DirectionField field;
    for (int v = 0; v < m.vertexCount(); ++v) {
        field.normals.push_back(n);
        field.directions.push_back(rotateRepresentative(d, n, (v * 5) % 6));  // mixed representatives
    }
    for (int f = 0; f < m.faceCount(); ++f)
        for (const Vec3& bary : {Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3), Vec3(0.7, 0.2, 0.1), Vec3(0.05, 0.05, 0.9)}) {
            const FieldSample s = interpolateField(m, field, f, bary);
            EXPECT_LT((s.normal - n).norm(), 1e-14);
            EXPECT_LT(setDistance(s.direction, d, n), 1e-12);
        }
}

TEST(Interpolation, CornerGivesTheVertexField)
{
    const TriMesh m = testmesh::icosphere(2);
    const DirectionField field = sphereField(m, 5);
    for (int f = 0; f < m.faceCount(); f += 3)
        for (int corner = 0; corner < 3; ++corner) {
            Vec3 bary = Vec3::Zero();
            bary[corner] = 1;
            const int v = m.faces[f][corner];
            const FieldSample s = interpolateField(m, field, f, bary);
            EXPECT_LT((s.normal - field.normals[v]).norm(), 1e-14);
            EXPECT_LT(setDistance(s.direction, field.directions[v], field.normals[v]), 1e-12);
        }
}

TEST(Interpolation, ContinuousAcrossEdges)
{
    // A point on an edge depends only on the edge's two vertices: both faces agree.
    const TriMesh m = testmesh::icosphere(2);
    const DirectionField field = sphereField(m, 9);
    int checked = 0;
    for (int f = 0; f < m.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
            for (int g = f + 1; g < m.faceCount(); ++g)
                for (int l = 0; l < 3; ++l)
                    if (m.faces[g][l] == b && m.faces[g][(l + 1) % 3] == a) {
                        Vec3 bf = Vec3::Zero(), bg = Vec3::Zero();
                        bf[k] = 0.3, bf[(k + 1) % 3] = 0.7;
                        bg[(l + 1) % 3] = 0.3, bg[l] = 0.7;
                        const FieldSample sf = interpolateField(m, field, f, bf);
                        const FieldSample sg = interpolateField(m, field, g, bg);
                        EXPECT_LT((sf.normal - sg.normal).norm(), 1e-12);
                        EXPECT_LT(setDistance(sf.direction, sg.direction, sf.normal), 1e-12);
                        ++checked;
                    }
        }
    EXPECT_EQ(checked, m.faceCount() * 3 / 2);
}

// The search skips pairs of representatives that cannot beat the best sum so far (a bound with a
// margin): the answer must be, bit for bit, the first maximum over all 108 sums, computed here the
// plain way, on smooth and on rough fields.
TEST(Interpolation, SkippedSumsNeverChangeTheAnswer)
{
    const TriMesh m = testmesh::torus(24, 12);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int smoothing : {2, 20}) {
        FieldParams params;
        params.smoothingIterations = smoothing;
        const DirectionField field = computeField(m, params);
        for (int f = 0; f < m.faceCount(); ++f) {
            double a = unit(rng), b = unit(rng);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            const Vec3 w(a, b, 1 - a - b);
            const FieldSample got = interpolateField(m, field, f, w);
            // The plain search (the normal as interpolateField computes it).
            const Face& t = m.faces[f];
            Vec3 n = w[0] * field.normals[t[0]] + w[1] * field.normals[t[1]] + w[2] * field.normals[t[2]];
            n /= n.norm();
            Vec3 r[3][6];
            for (int v = 0; v < 3; ++v)
                for (int k = 0; k < 3; ++k) {
                    const Vec3 c = field.normals[t[v]].cross(field.directions[t[v]]);
                    const Vec3& d = field.directions[t[v]];
                    const Vec3 rep = k == 0 ? d : k == 1 ? Vec3(0.5 * d + rosy::kSin60 * c) : Vec3(-0.5 * d + rosy::kSin60 * c);
                    r[v][k] = w[v] * rep;
                    r[v][k + 3] = -r[v][k];
                }
            double best = -1;
            Vec3 bestSum = Vec3::Zero();
            for (int ka = 0; ka < 3; ++ka)
                for (int kb = 0; kb < 6; ++kb)
                    for (int kc = 0; kc < 6; ++kc) {
                        const Vec3 sum = (r[0][ka] + r[1][kb]) + r[2][kc];
                        const double nd = n.dot(sum);
                        const double value = sum.squaredNorm() - nd * nd;
                        if (value > best) best = value, bestSum = sum;
                    }
            const Vec3 d = rosy::projectTangent(bestSum, n);
            const Vec3 expected = d / d.norm();
            ASSERT_EQ(got.direction.x(), expected.x()) << "face " << f << ", smoothing " << smoothing;
            ASSERT_EQ(got.direction.y(), expected.y());
            ASSERT_EQ(got.direction.z(), expected.z());
        }
    }
}
