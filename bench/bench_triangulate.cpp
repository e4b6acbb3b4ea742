// Polygon triangulation (core/triangulate.h, issue 30): a concave polygon of N corners, as a
// mesh file's face. Ear clipping below kMaxEarClippingCorners, the constrained Delaunay
// triangulation above: the time per polygon should grow about as N log N.
#include "triangulate.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace fieldcvt;

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
    std::vector<Face> faces;
    for (auto _ : state) {
        faces.clear();
        benchmark::DoNotOptimize(triangulatePolygon(points, corners, faces));
    }
    state.SetComplexityN(n);
}
BENCHMARK(BM_TriangulateLobedPolygon)->Arg(1000)->Arg(10000)->Arg(100000)
    ->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oNLogN);
// Small polygons (quads, hexagons: most polygon faces of files) on both sides of the threshold.
BENCHMARK(BM_TriangulateLobedPolygon)->Name("BM_TriangulateSmallPolygon")->Arg(4)->Arg(8)->Arg(32)->Arg(64)->Arg(65)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
