// The strip sizing of the local remeshing (core/strip_sizing.h): short edges on a strip between
// two creases narrower than the length (a thin plate's rim), the length itself far from it and
// wherever no strip is narrower than the length, never a jump steeper than the gradation.
#include "strip_sizing.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace fieldcvt;

namespace {

constexpr double kLength = 1.0746;

}  // namespace

TEST(StripSizing, ThinPlateRimGetsEdgesAsLongAsItIsWide)
{
    const TriMesh plate = testmesh::scaledThinBox(12.0, 0.24);  // 12 x 0.24 x 12: rims 0.24 wide
    const StripSizingParams params;
    const StripSizing sizing(plate, std::vector<char>(plate.faces.size(), 1), kLength, params);
    ASSERT_GT(sizing.sources(), 0);
    EXPECT_NEAR(sizing.smallest(), params.widthShare * 0.24, 1e-9);
    // On the rim: about 1.5 widths (the nearest crease point within a quarter length).
    const double rim = sizing.at(Vec3(6.0, 0.12, 0.0));
    EXPECT_GE(rim, params.widthShare * 0.24 - 1e-12);
    EXPECT_LT(rim, params.widthShare * 0.24 + params.gradation * 0.25 * kLength);
    // Graded back to the length across the flat faces; the length in their middle.
    const double near = sizing.at(Vec3(6.0, 0.24, 0.5));
    EXPECT_GT(near, rim);
    EXPECT_LT(near, kLength);
    EXPECT_EQ(sizing.at(Vec3(6.0, 0.24, 6.0)), kLength);
}

TEST(StripSizing, NoStripNarrowerThanTheLengthLeavesTheLength)
{
    const TriMesh cube = testmesh::scaledThinBox(10.0, 10.0);  // creases 10 lengths apart
    const StripSizing sizing(cube, std::vector<char>(cube.faces.size(), 1), kLength);
    EXPECT_EQ(sizing.sources(), 0);
    EXPECT_EQ(sizing.at(Vec3(0.0, 0.0, 0.0)), kLength);
    // Unselected faces count for nothing: the thin plate's rims are not strips then.
    const TriMesh plate = testmesh::scaledThinBox(12.0, 0.24);
    const StripSizing none(plate, std::vector<char>(plate.faces.size(), 0), kLength);
    EXPECT_EQ(none.sources(), 0);
}

TEST(StripSizing, NeverSteeperThanTheGradation)
{
    const TriMesh plate = testmesh::scaledThinBox(12.0, 0.24);
    const StripSizingParams params;
    const StripSizing sizing(plate, std::vector<char>(plate.faces.size(), 1), kLength, params);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 13.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 p(coordinate(random), coordinate(random) / 12.0, coordinate(random));
        const Vec3 q = p + 0.3 * Vec3(coordinate(random), coordinate(random), coordinate(random)).normalized();
        const double a = sizing.at(p), b = sizing.at(q);
        ASSERT_LE(std::abs(a - b), params.gradation * (p - q).norm() + 1e-12);
        ASSERT_GE(std::min(a, b), sizing.smallest() - 1e-12);
        ASSERT_LE(std::max(a, b), kLength);
    }
}
