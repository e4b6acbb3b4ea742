// The 6-RoSy field (paper §3.2–3.3, §4.1): smoothness, constraints, curvature sources,
// singularities, determinism.
#include "errors.h"
#include "field.h"
#include "field_hierarchy.h"
#include "interpolation.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "metrics.h"
#include "test_meshes.h"
#include "thread_count.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <numeric>

using namespace fieldcvt;

namespace {

// Smallest angle (degrees) between the line of `axis` and the six directions of (d, n).
double angleToField(const Vec3& d, const Vec3& n, const Vec3& axis)
{
    const Vec3 a = axis.normalized();
    double best = 1e300;
    for (int k = 0; k < 3; ++k) {
        // atan2 rather than acos: accurate to ~1e-16 near 0 (acos only to ~1e-8).
        const Vec3 r = rotateRepresentative(d, n, k);
        best = std::min(best, std::atan2(r.cross(a).norm(), std::abs(r.dot(a))));
    }
    return best * 180 / kPi;
}

int indexSum(const std::vector<Singularity>& s)
{
    return std::accumulate(s.begin(), s.end(), 0, [](int sum, const Singularity& x) { return sum + x.index; });
}

int eulerCharacteristic(const TriMesh& m)
{
    const TopologySummary t = computeTopology(m);
    return t.vertices - t.edges + t.faces;
}

void expectUnitTangent(const DirectionField& field, int vertices)
{
    ASSERT_EQ(static_cast<int>(field.normals.size()), vertices);
    ASSERT_EQ(static_cast<int>(field.directions.size()), vertices);
    for (int v = 0; v < vertices; ++v) {
        ASSERT_NEAR(field.normals[v].norm(), 1.0, 1e-12) << v;
        ASSERT_NEAR(field.directions[v].norm(), 1.0, 1e-12) << v;
        ASSERT_NEAR(field.directions[v].dot(field.normals[v]), 0.0, 1e-12) << v;
    }
}

// Open cylinder of radius r around the z axis, z in [0, height], rows shifted by half a step
// so the triangles are nearly equilateral.
TriMesh cylinder(int around, int rows, double r, double height)
{
    TriMesh m;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < around; ++i) {
            const double a = 2 * kPi * (i + 0.5 * (j % 2)) / around;
            m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), height * j / rows);
        }
    auto id = [around](int i, int j) { return j * around + (i % around + around) % around; };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < around; ++i) {
            if (j % 2 == 0) {
                m.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                m.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
                m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            }
        }
    return m;
}

//! The vertices' principal axes (columns, from the thinnest spread to the longest) and centroid.
Eigen::Matrix3d principalAxes(const TriMesh& m, Vec3& centre)
{
    centre = Vec3::Zero();
    for (const Vec3& p : m.vertices) centre += p;
    centre /= m.vertexCount();
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3& p : m.vertices) cov += (p - centre) * (p - centre).transpose();
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors();
}

TriMesh loadResource(const std::string& name)
{
    InputReport report;
    return prepareInput(readMesh(testmesh::resource(name)), report);
}

}  // namespace

TEST(Field, SourceNames)
{
    for (FieldSource s : {FieldSource::Extrinsic, FieldSource::CurvatureMax, FieldSource::CurvatureMin, FieldSource::User})
        EXPECT_EQ(fieldSourceFromName(fieldSourceName(s)), s);
    EXPECT_EQ(fieldSourceName(FieldSource::CurvatureMin), "curvature-min");
    EXPECT_THROW(fieldSourceFromName("curvature"), InvalidInputError);
    EXPECT_THROW(fieldSourceFromName(""), InvalidInputError);
}

TEST(Field, VertexNormalsOfSphereArePositions)
{
    const TriMesh m = testmesh::icosphere(3);
    const std::vector<Vec3> n = vertexNormals(m);
    for (int v = 0; v < m.vertexCount(); ++v) EXPECT_GT(n[v].dot(m.vertices[v]), 0.999);
    TriMesh isolated = testmesh::planeGrid(1);
    isolated.vertices.emplace_back(5, 5, 5);
    EXPECT_EQ(vertexNormals(isolated).back(), Vec3(0, 0, 1));
}

TEST(Field, ExtrinsicFieldIsUnitAndTangent)
{
    const TriMesh m = testmesh::torus(40, 20);
    expectUnitTangent(computeField(m, FieldParams{}), m.vertexCount());
}

TEST(Field, SmoothingLowersEnergyMonotonically)
{
    const TriMesh m = testmesh::icosphere(4);
    FieldReport report;
    const DirectionField field = computeField(m, FieldParams{}, &report);
    ASSERT_GE(report.levelVertexCounts.size(), 4u);
    EXPECT_EQ(report.levelVertexCounts.front(), m.vertexCount());
    EXPECT_LE(report.levelVertexCounts.back(), 60);
    for (std::size_t l = 1; l < report.levelVertexCounts.size(); ++l)
        EXPECT_LT(report.levelVertexCounts[l], 0.75 * report.levelVertexCounts[l - 1]);  // about halving

    // On the input mesh, level after level (entry 0: the random field; entry k: after level
    // L − k, coarsest first). Levels of a handful of vertices cannot place a sphere's twelve
    // singularities, so the prolongation of one of them may score worse than the next coarser
    // one's; from a few dozen vertices on, every level lowers the energy.
    const int levels = static_cast<int>(report.levelVertexCounts.size());
    ASSERT_EQ(static_cast<int>(report.levelEnergies.size()), levels + 1);
    for (int k = 1; k <= levels; ++k) {
        EXPECT_LT(report.levelEnergies[k], 0.2 * report.levelEnergies[0]);
        EXPECT_GE(report.levelEnergies[k], report.levelEnergies.back());
        if (report.levelVertexCounts[levels - k] >= 50 && k > 1 && report.levelVertexCounts[levels - k + 1] >= 50)
            EXPECT_LT(report.levelEnergies[k], report.levelEnergies[k - 1]) << "level " << levels - k;
    }
    EXPECT_LT(report.levelEnergies.back(), 0.05 * report.levelEnergies.front());
    EXPECT_NEAR(report.levelEnergies.back(), extrinsicEnergy(m, field), 1e-9 * report.levelEnergies.back());
    // Sweep after sweep within every level (guaranteed: each update minimises its vertex's
    // local energy for the current matching), and each level's smoothing helps.
    ASSERT_EQ(static_cast<int>(report.sweepEnergies.size()), levels);
    for (const std::vector<double>& sweeps : report.sweepEnergies) {
        ASSERT_EQ(sweeps.size(), 21u);  // before + 20 sweeps
        for (std::size_t s = 1; s < sweeps.size(); ++s) EXPECT_LE(sweeps[s], sweeps[s - 1] * (1 + 1e-12) + 1e-15);
        EXPECT_LT(sweeps.back(), sweeps.front());
    }
}

TEST(Field, PlanarGridGetsAConstantField)
{
    const TriMesh m = testmesh::planeGrid(24);
    FieldParams params;
    params.alignToBorder = false;  // a square's borders are 90° apart: no 6-RoSy fits all four
    const DirectionField field = computeField(m, params);
    EXPECT_LT(extrinsicEnergy(m, field), 1e-10);
    for (int v = 0; v < m.vertexCount(); ++v)
        EXPECT_LT(angleToField(field.directions[v], field.normals[v], field.directions[0]), 1e-3);
}

TEST(Field, BorderConstrainsTheField)
{
    const TriMesh m = testmesh::disk(8);
    FieldReport report;
    const DirectionField field = computeField(m, FieldParams{}, &report);
    expectUnitTangent(field, m.vertexCount());
    const int firstBorder = 1 + 3 * 7 * 8;  // ring 8 starts after 1 + 6 + 12 + ... + 42 vertices
    EXPECT_EQ(report.constrainedVertices, m.vertexCount() - firstBorder);
    for (int v = firstBorder; v < m.vertexCount(); ++v) {
        const Vec3 tangent(-m.vertices[v].y(), m.vertices[v].x(), 0);  // of the circle
        EXPECT_LT(angleToField(field.directions[v], field.normals[v], tangent), 1e-9 * 180 / kPi) << v;
    }
    // Without the constraint the border is free (and the field constant: the disk is flat).
    FieldParams free;
    free.alignToBorder = false;
    const DirectionField f2 = computeField(m, free);
    EXPECT_LT(extrinsicEnergy(m, f2), 1e-10);
    EXPECT_LT(extrinsicEnergy(m, f2), extrinsicEnergy(m, field));
}

TEST(Field, SharpEdgesConstrainTheField)
{
    // A cube-like box: every vertex of the unit-cube grid lies on or next to a 90° crease.
    TriMesh box;
    const TriMesh grid = testmesh::planeGrid(4);
    // Six faces of a cube from rotated copies of the grid (duplicated border vertices merged).
    std::vector<Vec3> verts;
    auto vertexId = [&](const Vec3& p) {
        for (std::size_t i = 0; i < verts.size(); ++i)
            if ((verts[i] - p).norm() < 1e-9) return static_cast<int>(i);
        verts.push_back(p);
        return static_cast<int>(verts.size()) - 1;
    };
    const Eigen::Matrix3d rotations[6] = {Eigen::Matrix3d::Identity(),
                                          Eigen::AngleAxisd(kPi, Vec3::UnitX()).toRotationMatrix(),
                                          Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()).toRotationMatrix(),
                                          Eigen::AngleAxisd(-kPi / 2, Vec3::UnitX()).toRotationMatrix(),
                                          Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()).toRotationMatrix(),
                                          Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()).toRotationMatrix()};
    for (const Eigen::Matrix3d& r : rotations)
        for (const Face& f : grid.faces) {
            Face g;
            for (int k = 0; k < 3; ++k) {
                // Grid in [0,1]^2 at z = 0 → face of the cube [-0.5, 0.5]^3 at z = -0.5, outward.
                const Vec3 p = grid.vertices[f[k]] - Vec3(0.5, 0.5, 0.5);
                g[k] = vertexId(r * p);
            }
            box.faces.push_back({g[0], g[2], g[1]});  // z = -0.5 face points down
        }
    box.vertices = verts;
    ASSERT_EQ(computeTopology(box).genus, 0);
    ASSERT_EQ(computeTopology(box).boundaryLoops, 0);
    FieldReport report;
    const DirectionField field = computeField(box, FieldParams{}, &report);
    int onEdges = 0;
    for (int v = 0; v < box.vertexCount(); ++v) {
        const Vec3& p = box.vertices[v];
        int extreme = 0;
        Vec3 free = Vec3::Zero();
        for (int a = 0; a < 3; ++a) {
            if (std::abs(std::abs(p[a]) - 0.5) < 1e-9)
                ++extreme;
            else
                free[a] = 1;
        }
        if (extreme == 2) {  // on a cube edge, not a corner: aligned with the edge
            EXPECT_LT(angleToField(field.directions[v], field.normals[v], free), 1e-6) << v;
            ++onEdges;
        }
    }
    EXPECT_EQ(onEdges, 12 * 3);
    EXPECT_EQ(report.constrainedVertices, 12 * 3 + 8);
    // Creases disabled: nothing is constrained.
    FieldParams noCrease;
    noCrease.sharpAngle = 0;
    FieldReport r2;
    computeField(box, noCrease, &r2);
    EXPECT_EQ(r2.constrainedVertices, 0);
}

TEST(Field, SameSeedSameFieldWithOneOrTwoThreads)
{
    const TriMesh m = testmesh::torus(240, 120);
    {  // colour classes large enough for the smoothing to run on threads (field_hierarchy.cpp)
        const auto hierarchy = buildFieldHierarchy(m, vertexNormals(m));
        const FieldGraph& g = hierarchy.levels[0];
        ASSERT_GE(m.vertexCount() / (static_cast<int>(g.colourOffsets.size()) - 1), 4096);
    }
    FieldParams params;
    params.seed = 42;
    const DirectionField one = testthreads::withThreadCount(1, [&] { return computeField(m, params); });
    const DirectionField two = testthreads::withThreadCount(2, [&] { return computeField(m, params); });
    ASSERT_EQ(one.directions.size(), two.directions.size());
    for (std::size_t v = 0; v < one.directions.size(); ++v) {
        ASSERT_EQ(one.directions[v], two.directions[v]) << v;  // bit for bit
        ASSERT_EQ(one.normals[v], two.normals[v]) << v;
    }
    params.seed = 43;
    const DirectionField other = computeField(m, params);
    int differing = 0;
    for (std::size_t v = 0; v < one.directions.size(); ++v) differing += !(other.directions[v] == one.directions[v]);
    EXPECT_GT(differing, 0);
}

TEST(Field, SingularityIndicesSumToSixTimesEulerCharacteristic)
{
    const TriMesh torus = testmesh::torus(48, 24);
    const TriMesh sphere = testmesh::icosphere(3);
    EXPECT_EQ(indexSum(findSingularities(torus, computeField(torus, FieldParams{}))), 0);
    const std::vector<Singularity> s = findSingularities(sphere, computeField(sphere, FieldParams{}));
    EXPECT_EQ(indexSum(s), 12);
    EXPECT_GE(s.size(), 2u);
    for (const Singularity& x : s) {
        EXPECT_NE(x.index, 0);
        EXPECT_LE(std::abs(x.index), 2);  // a smooth field has simple singularities
        const Face& f = sphere.faces[x.face];
        EXPECT_LT((x.position - (sphere.vertices[f[0]] + sphere.vertices[f[1]] + sphere.vertices[f[2]]) / 3).norm(), 1e-12);
    }
    // The identity holds for any field, even a random (unsmoothed) one, and on coarse meshes
    // whose faces carry more curvature than a sixth of a turn (the icosahedron: π/5 per face),
    // where the curvature term of the index is what keeps the sum.
    FieldParams rough;
    rough.smoothingIterations = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        rough.seed = seed;
        for (const TriMesh& m : {testmesh::icosphere(0), testmesh::icosphere(1), sphere})
            EXPECT_EQ(indexSum(findSingularities(m, computeField(m, rough))), 12) << seed;
        const TriMesh coarseTorus = testmesh::torus(7, 5);
        EXPECT_EQ(indexSum(findSingularities(coarseTorus, computeField(coarseTorus, rough))), 0) << seed;
    }
}

TEST(Field, SingularitiesOfFertilitySumToMinus36)
{
    const TriMesh m = loadResource("fertility.off");
    ASSERT_EQ(eulerCharacteristic(m), -6);  // genus 4
    const DirectionField field = computeField(m, FieldParams{});
    expectUnitTangent(field, m.vertexCount());
    const std::vector<Singularity> s = findSingularities(m, field);
    EXPECT_EQ(indexSum(s), -36);
    EXPECT_LT(s.size(), m.faces.size() / 50);  // smooth: few singular faces
}

TEST(Field, CurvatureDirectionsOnCylinder)
{
    const TriMesh m = cylinder(40, 24, 1.0, 3.0);
    FieldParams params;
    params.source = FieldSource::CurvatureMax;
    FieldReport report;
    const DirectionField fmax = computeField(m, params, &report);
    EXPECT_EQ(report.umbilicVertices, 0);
    params.source = FieldSource::CurvatureMin;
    const DirectionField fmin = computeField(m, params);
    expectUnitTangent(fmax, m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) {
        const Vec3 around(-m.vertices[v].y(), m.vertices[v].x(), 0);
        EXPECT_LT(angleToField(fmax.directions[v], fmax.normals[v], around), 3.0) << v;
        EXPECT_LT(angleToField(fmin.directions[v], fmin.normals[v], Vec3::UnitZ()), 3.0) << v;
        // Min and max are 90° apart: a 6-RoSy representative of one is 30° from the other.
        EXPECT_GT(angleToField(fmin.directions[v], fmin.normals[v], around), 25.0) << v;
    }
}

TEST(Field, CurvatureFallsBackToSmoothingWhereUmbilic)
{
    // A sphere is umbilic everywhere: the curvature field is the smooth extrinsic field.
    const TriMesh m = testmesh::icosphere(3);
    FieldParams params;
    params.source = FieldSource::CurvatureMax;
    FieldReport report;
    const DirectionField f = computeField(m, params, &report);
    expectUnitTangent(f, m.vertexCount());
    EXPECT_EQ(report.umbilicVertices, m.vertexCount());
    EXPECT_EQ(indexSum(findSingularities(m, f)), 12);
    EXPECT_LT(extrinsicEnergy(m, f), 0.2 * report.levelEnergies.front());
}

TEST(Field, TorusResourceCurvatureFields)
{
    // The check: min curvature along the circles around the axis, max around the tube,
    // within 5° at 95 % of the vertices.
    const TriMesh m = loadResource("torus.obj");
    Vec3 centre;
    const Vec3 axis = principalAxes(m, centre).col(0);  // thinnest
    FieldParams params;
    params.source = FieldSource::CurvatureMin;
    const DirectionField fmin = computeField(m, params);
    params.source = FieldSource::CurvatureMax;
    const DirectionField fmax = computeField(m, params);
    int goodMin = 0, goodMax = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
        const Vec3 around = axis.cross(m.vertices[v] - centre);
        const Vec3 tube = fmax.normals[v].cross(around);
        goodMin += angleToField(fmin.directions[v], fmin.normals[v], around) < 5.0;
        goodMax += angleToField(fmax.directions[v], fmax.normals[v], tube) < 5.0;
    }
    EXPECT_GE(goodMin, 0.95 * m.vertexCount());
    EXPECT_GE(goodMax, 0.95 * m.vertexCount());
}

TEST(Field, CylinderResourceExtrinsicFieldFollowsTheAxis)
{
    // The check, with the rims free: a rim tangent is 90° from the axis, which no
    // representative of an axis-aligned 6-RoSy field matches (30° off), so with the rims
    // constrained the rim vertices alone (6.5 %) could not pass.
    const TriMesh m = loadResource("cylinder.off");
    FieldParams params;
    params.alignToBorder = false;
    const DirectionField f = computeField(m, params);
    int good = 0;
    for (int v = 0; v < m.vertexCount(); ++v) good += angleToField(f.directions[v], f.normals[v], Vec3::UnitZ()) < 3.0;
    EXPECT_GE(good, 0.95 * m.vertexCount());
}

TEST(Field, CylinderResourceFieldWithBorderDoesNotTwist)
{
    // Issue 13: with the rims constrained (the default), one of the six directions within 3° of
    // the rings (or of the axis: the two cannot both hold, they are 30° apart mod 60°) at 95 %
    // of the vertices. The axis is the vertices' most elongated principal axis (checked: the z
    // axis through the origin for this mesh).
    const TriMesh m = loadResource("cylinder.off");
    Vec3 centre;
    const Vec3 axis = principalAxes(m, centre).col(2);  // longest
    EXPECT_GT(std::abs(axis.z()), 1 - 1e-6);
    EXPECT_LT(centre.norm(), 1e-3);
    FieldReport report;
    const DirectionField f = computeField(m, FieldParams{}, &report);
    EXPECT_GT(report.constrainedVertices, 0);
    expectUnitTangent(f, m.vertexCount());
    int rings = 0, axial = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
        const Vec3 around = axis.cross(m.vertices[v] - centre);
        rings += angleToField(f.directions[v], f.normals[v], around) < 3.0;
        axial += angleToField(f.directions[v], f.normals[v], axis) < 3.0;
    }
    std::printf("cylinder.off: %.1f %% of the vertices within 3 deg of the rings, %.1f %% of the axis\n",
                100.0 * rings / m.vertexCount(), 100.0 * axial / m.vertexCount());
    EXPECT_GE(std::max(rings, axial), 0.95 * m.vertexCount());
    EXPECT_TRUE(findSingularities(m, f).empty());
}

TEST(Field, BorderConstrainedFieldUsesTheIntrinsicEnergy)
{
    // The cause of issue 13's twist: with the extrinsic energy (which also pays for the tangent
    // planes turning) the rims' direction does not reach the middle of a cylinder; the
    // intrinsic one (Auto, because the border constrains the field) is zero for the
    // rim-aligned field, which then holds everywhere. Its sweeps never raise its energy.
    const TriMesh m = cylinder(40, 24, 1.0, 3.0);
    auto ringFraction = [&](const DirectionField& f) {
        int good = 0;
        for (int v = 0; v < m.vertexCount(); ++v) {
            const Vec3 around(-m.vertices[v].y(), m.vertices[v].x(), 0);
            good += angleToField(f.directions[v], f.normals[v], around) < 3.0;
        }
        return static_cast<double>(good) / m.vertexCount();
    };
    FieldParams params;
    FieldReport report;
    const DirectionField intrinsic = computeField(m, params, &report);
    EXPECT_EQ(ringFraction(intrinsic), 1.0);
    for (const std::vector<double>& sweeps : report.sweepEnergies)
        for (std::size_t k = 1; k < sweeps.size(); ++k) EXPECT_LE(sweeps[k], sweeps[k - 1] * (1 + 1e-12) + 1e-15);
    EXPECT_LT(report.levelEnergies.back(), 1e-6 * report.levelEnergies.front());
    params.smoothness = FieldSmoothness::Intrinsic;
    const DirectionField forced = computeField(m, params);
    for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(forced.directions[v], intrinsic.directions[v]) << v;
    params.smoothness = FieldSmoothness::Extrinsic;  // the former behaviour: it twists
    EXPECT_LT(ringFraction(computeField(m, params)), 0.5);
}

TEST(Field, UserVectors)
{
    const TriMesh m = testmesh::icosphere(2);
    std::vector<Vec3> vectors(m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) vectors[v] = Vec3::UnitZ().cross(m.vertices[v]) + 0.3 * m.vertices[v];
    // Near the poles UnitZ × p vanishes and the vector is (nearly) normal: filled by smoothing.
    const DirectionField f = fieldFromVectors(m, vectors);
    expectUnitTangent(f, m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) {
        const Vec3 t = vectors[v] - vectors[v].dot(f.normals[v]) * f.normals[v];
        if (t.norm() > 1e-2 * vectors[v].norm()) EXPECT_LT((f.directions[v] - t.normalized()).norm(), 1e-12) << v;
    }
    EXPECT_THROW(fieldFromVectors(m, std::vector<Vec3>(3, Vec3::UnitX())), InvalidInputError);
    vectors[0] = Vec3(std::nan(""), 0, 0);
    EXPECT_THROW(fieldFromVectors(m, vectors), InvalidInputError);
    FieldParams user;
    user.source = FieldSource::User;
    EXPECT_THROW(computeField(m, user), InvalidInputError);
}

TEST(Field, FandiskFieldFollowsSharpEdges)
{
    // The check: within 5° of the sharp edge (dihedral angle above 60°) at 95 % of the
    // vertices along sharp edges.
    const TriMesh m = loadResource("fandisk.off");
    const DirectionField f = computeField(m, FieldParams{});
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (int t = 0; t < m.faceCount(); ++t)
        for (int k = 0; k < 3; ++k) edgeFaces[std::minmax(m.faces[t][k], m.faces[t][(k + 1) % 3])].push_back(t);
    std::vector<std::vector<Vec3>> sharpTangents(m.vertexCount());
    for (const auto& [edge, faces] : edgeFaces) {
        if (faces.size() != 2) continue;
        const Vec3 n0 = faceNormal(m, faces[0]).normalized(), n1 = faceNormal(m, faces[1]).normalized();
        if (std::acos(std::clamp(n0.dot(n1), -1.0, 1.0)) * 180 / kPi <= 60) continue;
        const Vec3 t = m.vertices[edge.second] - m.vertices[edge.first];
        sharpTangents[edge.first].push_back(t);
        sharpTangents[edge.second].push_back(t);
    }
    int onSharp = 0, aligned = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
        const std::vector<Vec3>& t = sharpTangents[v];
        if (t.empty()) continue;
        ++onSharp;
        double best = 180;
        if (t.size() == 2) {  // along a crease: its tangent there, the mean of the two edges
            const Vec3 tangent = t[0].normalized() + (t[0].dot(t[1]) < 0 ? -1.0 : 1.0) * t[1].normalized();
            best = angleToField(f.directions[v], f.normals[v], tangent);
        } else {  // a corner or an end: any of its edges
            for (const Vec3& e : t) best = std::min(best, angleToField(f.directions[v], f.normals[v], e));
        }
        aligned += best < 5.0;
    }
    EXPECT_GT(onSharp, 50);
    EXPECT_GE(aligned, 0.95 * onSharp) << aligned << " of " << onSharp;
}
