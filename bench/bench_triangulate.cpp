// Polygon triangulation (core/triangulate.h, issue 30): a concave polygon of N corners, as a
// mesh file's face. Ear clipping below kMaxEarClippingCorners, the constrained Delaunay
// triangulation above: the time per polygon should grow about as N log N.
#include "triangulate.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace fieldcvt;

//! Triangulates the polygon `corners` of `points` once per iteration (N = state.range(0), the
//! corner count, for the complexity fit).
void timeTriangulation(benchmark::State& state, const std::vector<Vec3>& points, const std::vector<int>& corners)
{
    std::vector<Face> faces;
    for (auto _ : state) {
        faces.clear();
        benchmark::DoNotOptimize(triangulatePolygon(points, corners, faces));
    }
    state.SetComplexityN(state.range(0));
}

//! 1000, 10 000 and 100 000 corners, fitted to N log N.
void largePolygons(benchmark::internal::Benchmark* b)
{
    b->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oNLogN);
}

void BM_TriangulateLobedPolygon(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    std::vector<Vec3> points;
    std::vector<int> corners;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n, r = 1 + 0.4 * std::cos(6 * a);
        points.push_back({r * std::cos(a), r * std::sin(a), 0});
        corners.push_back(i);
    }
    timeTriangulation(state, points, corners);
}
BENCHMARK(BM_TriangulateLobedPolygon)->Apply(largePolygons);
// A strip wound 10 times (two arms of N / 2 corners, 1 apart, 0.5 wide): long thin channels,
// the case ear clipping is slowest on and where a sweep's monotone pieces are many.
void BM_TriangulateSpiralPolygon(benchmark::State& state)
{
    const int arm = static_cast<int>(state.range(0)) / 2;
    std::vector<Vec3> points;
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k < arm; ++k) {
            const int i = side ? arm - 1 - k : k;
            const double a = 20 * M_PI * i / (arm - 1), r = (side ? 0.5 : 1.0) + a / (2 * M_PI);
            points.push_back({r * std::cos(a), r * std::sin(a), 0});
        }
    std::vector<int> corners(points.size());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<int>(i);
    timeTriangulation(state, points, corners);
}
BENCHMARK(BM_TriangulateSpiralPolygon)->Apply(largePolygons);
// Small polygons (quads, hexagons: most polygon faces of files) on both sides of the threshold.
BENCHMARK(BM_TriangulateLobedPolygon)
    ->Name("BM_TriangulateSmallPolygon")
    ->Arg(4)
    ->Arg(8)
    ->Arg(32)
    ->Arg(64)
    ->Arg(65)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
