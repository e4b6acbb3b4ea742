// Speed of one energy + gradient evaluation (the RVD pass dominates every stage of FCVT) and of
// a whole remesh. Run: build/bench/fcvt_bench [--benchmark_filter=...]
// Compare medians, and thread counts within one run: the machine is shared and noisy.
#include "energy.h"
#include "mesh_check.h"
#include "mesh_io.h"
#include "optimize.h"
#include "remesh.h"
#include "rvd.h"
#include "sampling.h"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>

using namespace fieldcvt;

namespace {

// bunny.obj at the working scale (mean cell area 1) with Lloyd-relaxed samples, as during L-BFGS.
struct BunnySetup {
    TriMesh surface;
    std::vector<Vec3> seeds;
    explicit BunnySetup(int samples)
    {
        InputReport report;
        surface = prepareInput(readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj"), report);
        const double scale = std::sqrt(samples / surfaceArea(surface));
        for (Vec3& p : surface.vertices) p *= scale;
        seeds = sampleSurfaceUniform(surface, samples, 1);
        EnergyFunction energy(surface);
        lloydRelaxation(energy, surface, seeds, 5, 1);
    }
};

const BunnySetup& bunny5000()
{
    static const BunnySetup setup(5000);
    return setup;
}

void BM_EnergyEvaluationBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    EnergyFunction energy(setup.surface);
    Eigen::VectorXd x = flatten(setup.seeds), gradient;
    for (auto _ : state) benchmark::DoNotOptimize(energy.evaluate(x, gradient).total);
    state.counters["clipped_polygons"] = static_cast<double>(energy.lastDiagram().clippedPolygons);
}
BENCHMARK(BM_EnergyEvaluationBunny5000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The RVD with its edges (the weights of E_field), as every FCVT evaluation needs it.
void BM_RvdWithEdgesBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    RestrictedVoronoiDiagram rvd(setup.surface);
    RvdResult result;
    RvdOptions options;
    options.edges = true;
    for (auto _ : state) {
        rvd.compute(setup.seeds, options, result);
        benchmark::DoNotOptimize(result.edges.data());
    }
    state.counters["edges"] = static_cast<double>(result.edges.size());
}
BENCHMARK(BM_RvdWithEdgesBunny5000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RemeshBunny5000(benchmark::State& state)
{
    const TriMesh input = readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj");
    RemeshParams params;
    params.vertexCount = 5000;
    params.threads = static_cast<int>(state.range(0));
    params.computeDistances = false;
    for (auto _ : state) {
        RemeshResult result = remesh(input, params);
        for (const StageTime& s : result.stageTimes) state.counters[s.stage + "_s"] = s.seconds;
        state.counters["evaluations"] = result.evaluations;
    }
}
BENCHMARK(BM_RemeshBunny5000)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
