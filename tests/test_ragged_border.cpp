// Borders with detail below the edge length (issue 32, item 1): the staircase outline of a range
// scan's grid, with notches one grid cell wide. The output's triangles stay well shaped there.
#include "metrics.h"
#include "remesh.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

using namespace fieldcvt;

namespace {

//! A height field over a `cells` x `cells` grid of [-1, 1]^2, keeping the squares whose centre
//! is inside a wavy circle and outside `notches` radial slits one square wide and 0.3 long:
//! a range map's ragged border (steps of one grid square).
TriMesh scanPatch(int cells, int notches)
{
    const double h = 2.0 / cells;
    auto kept = [&](int i, int j) {
        const double x = -1 + (i + 0.5) * h, y = -1 + (j + 0.5) * h;
        const double r = std::hypot(x, y), angle = std::atan2(y, x);
        if (r > 0.9 + 0.04 * std::sin(9 * angle)) return false;
        for (int k = 0; k < notches; ++k) {
            const double a = 2 * kPi * (k + 0.3) / notches;  // the slit's direction
            const double along = x * std::cos(a) + y * std::sin(a), across = -x * std::sin(a) + y * std::cos(a);
            if (along > 0.6 && std::abs(across) < 0.5 * h) return false;
        }
        return true;
    };
    TriMesh m;
    std::vector<int> index((cells + 1) * (cells + 1), -1);
    auto vertex = [&](int i, int j) {
        int& v = index[j * (cells + 1) + i];
        if (v < 0) {
            const double x = -1 + i * h, y = -1 + j * h;
            v = m.vertexCount();
            m.vertices.emplace_back(x, y, 0.15 * std::sin(2 * x) * std::cos(3 * y));
        }
        return v;
    };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (!kept(i, j)) continue;
            const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            if ((i + j) % 2 == 0) {
                m.faces.push_back({a, b, c});
                m.faces.push_back({a, c, d});
            } else {
                m.faces.push_back({a, b, d});
                m.faces.push_back({b, c, d});
            }
        }
    return m;
}

int zeroAreaFaces(const TriMesh& mesh)
{
    int count = 0;
    for (const Face& f : mesh.faces) {
        const Vec3& a = mesh.vertices[f[0]];
        count += ((mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).array() == 0.0).all();
    }
    return count;
}

}  // namespace

// Issue 32's bounds, borders included: no zero-area face, no angle under 15°, at least 99.5 % of
// the triangles with every angle at or above 30°; with edges of about 2 and 4 grid squares
// (before, on the first: a smallest angle of 1.3°, 2.3 % of the triangles under 30°).
TEST(RaggedBorder, ScanPatchKeepsTrianglesWellShapedAlongItsStaircaseBorder)
{
    for (const auto& [cells, vertices] : {std::pair{60, 1000}, std::pair{100, 500}}) {
        RemeshParams p;
        p.vertexCount = vertices;
        p.computeDistances = false;
        const RemeshResult r = remesh(scanPatch(cells, 5), p);
        SCOPED_TRACE(std::to_string(cells) + " squares across, " + std::to_string(vertices) + " vertices");
        EXPECT_EQ(zeroAreaFaces(r.mesh), 0);
        EXPECT_GE(r.metrics.thetaMin, 15.0);
        EXPECT_LE(r.metrics.pctLt30, 0.5);
        EXPECT_GE(r.outputTopology.boundaryLoops, 1);
    }
}
