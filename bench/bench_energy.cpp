// Speed of one energy + gradient evaluation (the RVD pass dominates every stage of FCVT) and of
// a whole remesh. Run: build/bench/fcvt_bench [--benchmark_filter=...]
// Compare medians, and thread counts within one run: the machine is shared and noisy.
#include "energy.h"
#include "mesh_check.h"
#include "mesh_edges.h"
#include "morton_order.h"
#include "mesh_io.h"
#include "optimize.h"
#include "rdt.h"
#include "field.h"
#include "lattice.h"
#include "metrics.h"
#include "valence.h"
#include "closest_point.h"
#include "remesh.h"
#include "repair.h"
#include "rvd.h"
#include "sampling.h"
#include "simplify.h"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <map>

using namespace fieldcvt;

namespace {

//! Scales `surface` to the working scale of `samples` samples (mean cell area 1) and returns that
//! many samples on it after 5 Lloyd steps, as L-BFGS starts from them.
std::vector<Vec3> relaxedSamples(TriMesh& surface, int samples)
{
    const double scale = std::sqrt(samples / surfaceArea(surface));
    for (Vec3& p : surface.vertices) p *= scale;
    std::vector<Vec3> seeds = sampleSurfaceUniform(surface, samples, 1);
    EnergyFunction energy(surface);
    lloydRelaxation(energy, surface, seeds, 5, 1);
    return seeds;
}

//! Energy + gradient evaluations of `energy` at `seeds`, timed.
void timeEvaluations(benchmark::State& state, EnergyFunction& energy, const std::vector<Vec3>& seeds)
{
    Eigen::VectorXd x = flatten(seeds), gradient;
    for (auto _ : state) benchmark::DoNotOptimize(energy.evaluate(x, gradient).total);
}

// bunny.obj at the working scale (mean cell area 1) with Lloyd-relaxed samples, as during L-BFGS.
struct BunnySetup {
    TriMesh surface;
    std::vector<Vec3> seeds;
    explicit BunnySetup(int samples)
    {
        InputReport report;
        surface = prepareInput(readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj"), report);
        seeds = relaxedSamples(surface, samples);
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
    timeEvaluations(state, energy, setup.seeds);
    state.counters["clipped_polygons"] = static_cast<double>(energy.lastDiagram().clippedPolygons);
}
BENCHMARK(BM_EnergyEvaluationBunny5000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same with seeds that move between evaluations, as in L-BFGS (each seed by 0.02 of the
// working unit per step, back and forth over 10 steps): what the RVD's neighbour lists see.
void BM_EnergyEvaluationMovingSeedsBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    EnergyFunction energy(setup.surface);
    std::vector<Vec3> step(setup.seeds.size());
    std::uint64_t h = 88172645463325252ULL;
    for (Vec3& d : step) {
        for (int c = 0; c < 3; ++c) {
            h ^= h << 13, h ^= h >> 7, h ^= h << 17;
            d[c] = double(h % 2001) / 1000.0 - 1.0;
        }
        d = 0.02 * d.normalized();
    }
    std::vector<Eigen::VectorXd> path;
    for (int k = 0; k < 20; ++k) {
        std::vector<Vec3> seeds = setup.seeds;
        const int along = k < 10 ? k : 20 - k;
        for (size_t i = 0; i < seeds.size(); ++i) seeds[i] += along * step[i];
        path.push_back(flatten(seeds));
    }
    Eigen::VectorXd gradient;
    size_t k = 0;
    long long fromCandidates = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(energy.evaluate(path[k++ % path.size()], gradient).total);
        fromCandidates += energy.lastDiagram().listsFromCandidates;
    }
    state.counters["lists_from_candidates"] = double(fromCandidates) / double(k * setup.seeds.size());
}
BENCHMARK(BM_EnergyEvaluationMovingSeedsBunny5000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The evaluations of real L-BFGS iterations on E_CVT from the Lloyd-relaxed bunny samples (the
// CVT stage's mix: most steps small, a few seeds jumping, line-search trials): what the RVD's
// candidate lists, movers and fallbacks see in the pipeline, per evaluation.
void BM_CvtLbfgsBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    long long evaluations = 0;
    for (auto _ : state) {
        EnergyFunction energy(setup.surface);
        std::vector<Vec3> seeds = setup.seeds;
        minimizeLbfgs(energy, seeds, LbfgsParams{10});
        evaluations += energy.evaluations();
    }
    state.counters["evaluations"] = double(evaluations) / double(state.iterations());  // per 10 iterations
}
BENCHMARK(BM_CvtLbfgsBunny5000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

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

// The regime of the scale run (nefertiti x 16 faces, 100k samples): about 16 input triangles
// per cell, most of them wholly inside one cell. bunny.obj subdivided once (1 -> 4) with 17k
// Lloyd-relaxed samples.
TriMesh subdivide(const TriMesh& mesh)
{
    TriMesh fine;
    fine.vertices = mesh.vertices;
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        const auto it = midpoint.find(key);
        if (it != midpoint.end()) return it->second;
        fine.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
        return midpoint[key] = fine.vertexCount() - 1;
    };
    for (const Face& f : mesh.faces) {
        const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
        fine.faces.push_back({f[0], ab, ca});
        fine.faces.push_back({f[1], bc, ab});
        fine.faces.push_back({f[2], ca, bc});
        fine.faces.push_back({ab, bc, ca});
    }
    return fine;
}

struct DenseSetup {
    TriMesh surface;
    std::vector<Vec3> seeds;
    DirectionField field;
    DenseSetup()
    {
        InputReport report;
        surface = subdivide(prepareInput(readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj"), report));
        seeds = relaxedSamples(surface, surface.faceCount() / 16);
        field = computeField(surface, FieldParams{});
    }
};

//! One setup per process, built on first use (outside the timed loops).
template <class Setup>
const Setup& shared()
{
    static const Setup setup;
    return setup;
}

const DenseSetup& dense() { return shared<DenseSetup>(); }

// One CVT evaluation (RVD without edges), as in the Lloyd and CVT stages.
void BM_CvtEvaluationDense(benchmark::State& state)
{
    const DenseSetup& setup = dense();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    EnergyFunction energy(setup.surface);
    timeEvaluations(state, energy, setup.seeds);
    state.counters["faces"] = setup.surface.faceCount();
    state.counters["samples"] = static_cast<double>(setup.seeds.size());
}
BENCHMARK(BM_CvtEvaluationDense)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// One FCVT evaluation: RVD with edges, field frames at the samples, E_field. The samples move
// a little between evaluations, as during L-BFGS (two positions alternate).
void BM_FcvtEvaluationDense(benchmark::State& state)
{
    const DenseSetup& setup = dense();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    EnergyFunction energy(setup.surface);
    ClosestPointTree tree(setup.surface);
    energy.setField(&setup.field, &tree, 0.002);
    Eigen::VectorXd x0 = flatten(setup.seeds), gradient;
    Eigen::VectorXd x1 = x0;
    for (Eigen::Index k = 0; k < x1.size(); ++k) x1[k] += 1e-3 * std::sin(static_cast<double>(k));
    bool odd = false;
    for (auto _ : state) {
        benchmark::DoNotOptimize(energy.evaluate(odd ? x1 : x0, gradient).total);
        odd = !odd;
    }
}
BENCHMARK(BM_FcvtEvaluationDense)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The extrinsic 6-RoSy field on the dense surface (140k vertices).
void BM_FieldDense(benchmark::State& state)
{
    const DenseSetup& setup = dense();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(computeField(setup.surface, FieldParams{}).directions.data());
}
BENCHMARK(BM_FieldDense)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The final RVD with its triangles and cell pieces, and the output mesh.
void BM_RdtDense(benchmark::State& state)
{
    const DenseSetup& setup = dense();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    RestrictedVoronoiDiagram rvd(setup.surface);
    ClosestPointTree tree(setup.surface);
    RvdResult result;
    RvdOptions options;
    options.triangles = true;
    for (auto _ : state) {
        rvd.compute(setup.seeds, options, result);
        benchmark::DoNotOptimize(extractRdt(setup.seeds, result.triangles, tree).mesh.faces.data());
    }
}
BENCHMARK(BM_RdtDense)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The stages after the optimisation, on the mesh they see in a default run: fertility.off at
// 3000 samples (10 Lloyd steps, 30 CVT iterations), its RDT, the extrinsic field.
struct FertilitySetup {
    TriMesh surface;
    DirectionField field;
    TriMesh rdt;
    FertilitySetup()
    {
        InputReport report;
        surface = prepareInput(readMesh(std::string(FCVT_RESOURCES_DIR) + "/fertility.off"), report);
        const double scale = std::sqrt(3000 / surfaceArea(surface));
        for (Vec3& p : surface.vertices) p *= scale;
        std::vector<Vec3> seeds = sampleSurfaceUniform(surface, 3000, 1);
        EnergyFunction energy(surface);
        lloydRelaxation(energy, surface, seeds, 10, 1);
        minimizeLbfgs(energy, seeds, LbfgsParams{30});
        field = computeField(surface, FieldParams{});
        ClosestPointTree tree(surface);
        RvdOptions options;
        options.triangles = true;
        rdt = extractRdt(seeds, energy.diagram(seeds, options), tree).mesh;
    }
};

const FertilitySetup& fertility3000() { return shared<FertilitySetup>(); }

// The start of the optimisation on fertility.off at 3000 samples: the lattice points of the
// position field (the default, lattice.h) against the random samples it replaces, with the
// Lloyd steps that follow either (arg 0: random; 1: lattice; 2: lattice without Lloyd steps).
void BM_StartFertility3000(benchmark::State& state)
{
    const FertilitySetup& setup = fertility3000();
    omp_set_num_threads(2);
    EnergyFunction energy(setup.surface);
    ClosestPointTree tree(setup.surface);
    for (auto _ : state) {
        std::vector<Vec3> seeds;
        if (state.range(0) == 0) {
            seeds = sampleSurfaceUniform(setup.surface, 3000, 1);
        } else {
            seeds = latticeSamples(setup.surface, setup.field, 3000, LatticeParams{});
            for (Vec3& p : seeds) p = tree.closest(p).point;
        }
        if (state.range(0) != 2) lloydRelaxation(energy, setup.surface, seeds, 10, 1);
        benchmark::DoNotOptimize(seeds.data());
    }
}
BENCHMARK(BM_StartFertility3000)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The valence optimisation (operations, then the relaxation) with its default parameters.
void BM_ValenceFertility3000(benchmark::State& state)
{
    const FertilitySetup& setup = fertility3000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    ClosestPointTree tree(setup.surface);
    const ValenceSurface on{setup.surface, tree, {}, &setup.field};
    for (auto _ : state) {
        TriMesh mesh = setup.rdt;
        std::vector<VertexRole> roles(mesh.vertices.size(), VertexRole::Free);
        benchmark::DoNotOptimize(optimizeValence(mesh, roles, on, ValenceParams{}).v6After);
    }
}
BENCHMARK(BM_ValenceFertility3000)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The valence stage's sag measure (distance from a face's centroid and edge midpoints to the
// surface) on the fertility 3000 RDT, one thread: Arg 0 the exact tree queries started from a
// corner's closest face (faceSag), Arg 1 the SurfaceWalk bounds from the same faces, which the
// stage now asks first (the tree only where a bound exceeds the limit).
void BM_SagQueriesFertility3000(benchmark::State& state)
{
    const FertilitySetup& setup = fertility3000();
    const ClosestPointTree tree(setup.surface);
    const SurfaceWalk walk(setup.surface);
    const TriMesh& mesh = setup.rdt;
    std::vector<int> cornerFace(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) cornerFace[v] = tree.closest(mesh.vertices[v]).face;
    const bool bounds = state.range(0) == 1;
    for (auto _ : state) {
        double largest = 0;
        for (const Face& t : mesh.faces) {
            const Vec3& a = mesh.vertices[t[0]];
            const Vec3& b = mesh.vertices[t[1]];
            const Vec3& c = mesh.vertices[t[2]];
            const Vec3 points[4] = {(a + b + c) / 3.0, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
            const int starts[4] = {cornerFace[t[0]], cornerFace[t[0]], cornerFace[t[1]], cornerFace[t[2]]};
            for (int k = 0; k < 4; ++k)
                largest = std::max(largest, bounds ? walk.distanceBound(points[k], starts[k])
                                                   : (tree.closest(points[k], starts[k]).point - points[k]).norm());
        }
        benchmark::DoNotOptimize(largest);
    }
    state.counters["queries"] = 4.0 * mesh.faceCount();
}
BENCHMARK(BM_SagQueriesFertility3000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// d_RMS / d_H of the metrics stage: threads, random samples per mesh (the report's 50 000 =
// RemeshParams::distanceSamples, against the dense 200 000 it took before and `fcvt metrics` takes).
void BM_DistanceFertility3000(benchmark::State& state)
{
    const FertilitySetup& setup = fertility3000();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    const int samples = static_cast<int>(state.range(1));
    for (auto _ : state) benchmark::DoNotOptimize(computeDistance(setup.rdt, setup.surface, samples).hausdorff);
}
BENCHMARK(BM_DistanceFertility3000)
    ->Args({1, 200000})
    ->Args({1, 50000})
    ->Args({2, 200000})
    ->Args({2, 50000})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The input side's serial stages on bunny.obj (69 451 faces, one thread): reading the OBJ file,
// and the repair with the strict check after it (the "prepare" stage).
void BM_ReadBunnyObj(benchmark::State& state)
{
    const std::string path = std::string(FCVT_RESOURCES_DIR) + "/bunny.obj";
    for (auto _ : state) benchmark::DoNotOptimize(readMesh(path).faces.size());
}
BENCHMARK(BM_ReadBunnyObj)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PrepareBunny(benchmark::State& state)
{
    const TriMesh input = readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj");
    RepairParams params;
    params.vertexBudget = 5000;
    for (auto _ : state) {
        RepairReport repair;
        InputReport report;
        benchmark::DoNotOptimize(repairAndPrepare(input, params, repair, report).faces.size());
    }
}
BENCHMARK(BM_PrepareBunny)->Unit(benchmark::kMillisecond)->UseRealTime();

// The simplification stage (one thread: it is serial) on bunny.obj at the working scale of
// 5000 samples, to the 20 000 faces the default pipeline optimises on.
void BM_SimplifyBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    SimplifyParams params;
    params.targetFaces = 4 * 5000;
    params.maxError = 0.05;
    for (auto _ : state) benchmark::DoNotOptimize(simplifyMesh(setup.surface, params).mesh.faces.size());
}
BENCHMARK(BM_SimplifyBunny5000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The edge table (mesh_edges.h) of bunny.obj (70 000 faces) and of it subdivided once (279 000),
// on 1 and 2 threads: every stage builds one, most of them on the input.
void BM_EdgeTable(benchmark::State& state)
{
    const TriMesh& mesh = state.range(0) ? dense().surface : bunny5000().surface;
    omp_set_num_threads(static_cast<int>(state.range(1)));
    for (auto _ : state) benchmark::DoNotOptimize(buildEdgeTable(mesh).edgeCount());
    state.counters["faces"] = mesh.faceCount();
}
BENCHMARK(BM_EdgeTable)->Args({0, 1})->Args({0, 2})->Args({1, 1})->Args({1, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

// The Morton order (morton_order.h) of the face centroids of bunny.obj subdivided once (279 000
// points), 1 and 2 threads: the simplification's blocks, the RVD's renumbering and the closest-
// point queries of every large run start with one.
void BM_MortonOrderDense(benchmark::State& state)
{
    const TriMesh& mesh = dense().surface;
    std::vector<Vec3> centroids;
    for (const Face& t : mesh.faces) centroids.push_back((mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0);
    omp_set_num_threads(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(mortonIndexOrder(centroids).data());
}
BENCHMARK(BM_MortonOrderDense)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The closest-point tree's build on bunny.obj subdivided once (279 000 faces), 1 and 2 threads
// (its subtrees below the top 3 levels are built on threads from 100 000 faces).
void BM_ClosestPointTreeBuildDense(benchmark::State& state)
{
    const TriMesh& mesh = dense().surface;
    omp_set_num_threads(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const ClosestPointTree tree(mesh);
        benchmark::DoNotOptimize(&tree);
    }
}
BENCHMARK(BM_ClosestPointTreeBuildDense)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The simplification of a dense surface (bunny.obj subdivided once, 279 000 faces, to a sixteenth
// of them), 2 threads: Arg 0 one pass; Arg 1 in 6 blocks in parallel, then one pass over the
// merged blocks (what inputs of 500 000 faces or more get by default).
void BM_SimplifyDense(benchmark::State& state)
{
    const DenseSetup& setup = dense();
    omp_set_num_threads(2);
    SimplifyParams params;
    params.targetFaces = setup.surface.faceCount() / 16;
    params.maxError = 0.05;
    params.blockFaces = state.range(0) ? setup.surface.faceCount() / 6 : 0;
    for (auto _ : state) benchmark::DoNotOptimize(simplifyMesh(setup.surface, params).mesh.faces.size());
    state.counters["blocks"] = simplifyBlockCount(setup.surface.faceCount(), params);
}
BENCHMARK(BM_SimplifyDense)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The border relaxation's diagram on mask.off (an open surface) at 4000 samples, 2 threads:
// Arg 0 every face clipped (as when it also moved the free samples), 1 only the faces along
// the border (RvdOptions::borderFacesOnly: the same border lengths and moments).
void BM_BorderDiagramMask4000(benchmark::State& state)
{
    struct MaskSetup {
        TriMesh surface;
        std::vector<Vec3> seeds;
        MaskSetup()
        {
            InputReport report;
            surface = prepareInput(readMesh(std::string(FCVT_RESOURCES_DIR) + "/mask.off"), report);
            const double scale = std::sqrt(4000 / surfaceArea(surface));
            for (Vec3& p : surface.vertices) p *= scale;
            seeds = sampleSurfaceUniform(surface, 4000, 1);
            EnergyFunction energy(surface);
            lloydRelaxation(energy, surface, seeds, 5, 1);
        }
    };
    static const MaskSetup setup;
    omp_set_num_threads(2);
    RestrictedVoronoiDiagram rvd(setup.surface);
    RvdResult result;
    RvdOptions options;
    options.boundary = true;
    options.borderFacesOnly = state.range(0) == 1;
    for (auto _ : state) {
        rvd.compute(setup.seeds, options, result);
        benchmark::DoNotOptimize(result.boundaryLength.data());
    }
}
BENCHMARK(BM_BorderDiagramMask4000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// E_field's frames at the bunny's 5000 samples, moved a little between calls as in L-BFGS, 2
// threads: Arg 0 a closest-point tree query per sample (no hints), 1 from the previous call's
// faces by a walk over the surface (EnergyFunction::framesAt with hints, what evaluate() does).
void BM_FieldFramesBunny5000(benchmark::State& state)
{
    const BunnySetup& setup = bunny5000();
    static const DirectionField field = computeField(setup.surface, FieldParams{});
    static const ClosestPointTree tree(setup.surface);
    omp_set_num_threads(2);
    EnergyFunction energy(setup.surface);
    energy.setField(&field, &tree, 0.002);
    std::vector<Vec3> points = setup.seeds;
    std::vector<int> faces;
    energy.framesAt(points, faces);
    int step = 0;
    for (auto _ : state) {
        const double shift = (step++ % 2 ? -0.02 : 0.02);
        for (size_t i = 0; i < points.size(); ++i) points[i] = setup.seeds[i] + Vec3(shift, -shift, shift);
        if (state.range(0) == 0)
            benchmark::DoNotOptimize(energy.framesAt(points).normals.data());
        else
            benchmark::DoNotOptimize(energy.framesAt(points, faces).normals.data());
    }
}
BENCHMARK(BM_FieldFramesBunny5000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole pipeline: Arg 1 the threads, Arg 2 the schedule (0: the defaults, 10 Lloyd + 10 CVT
// + 40 FCVT iterations with look-ahead 8; 1: the paper's fixed schedule after 30 Lloyd steps,
// 65 + 65, with the look-ahead of that time, 6).
void BM_RemeshBunny5000(benchmark::State& state)
{
    const TriMesh input = readMesh(std::string(FCVT_RESOURCES_DIR) + "/bunny.obj");
    RemeshParams params;
    params.vertexCount = 5000;
    params.threads = static_cast<int>(state.range(0));
    if (state.range(1) == 1) {
        usePaperSchedule(params);
        params.valence.lookAheadDepth = 6;
    }
    params.computeDistances = false;
    for (auto _ : state) {
        RemeshResult result = remesh(input, params);
        for (const StageTime& s : result.stageTimes) state.counters[s.stage + "_s"] = s.seconds;
        state.counters["evaluations"] = result.evaluations;
    }
}
BENCHMARK(BM_RemeshBunny5000)->Args({2, 0})->Args({2, 1})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
