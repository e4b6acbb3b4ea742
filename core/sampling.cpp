#include "sampling.h"

#include "disjoint_sets.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

namespace fieldcvt {

namespace {

// A uniform random point of face f: sqrt maps the first coordinate so the density is constant.
Vec3 randomPointIn(const TriMesh& surface, int f, std::mt19937_64& rng)
{
    const double r1 = std::sqrt(unitInterval(rng())), r2 = unitInterval(rng());
    const Face& t = surface.faces[f];
    return (1 - r1) * surface.vertices[t[0]] + r1 * (1 - r2) * surface.vertices[t[1]] + r1 * r2 * surface.vertices[t[2]];
}

// `count` points, each in a face picked ∝ area × weight (weight 1 when `weight` is null).
std::vector<Vec3> samplePoints(const TriMesh& surface, int count, std::uint64_t seed, const std::vector<double>* weight)
{
    std::vector<double> cumulative(surface.faces.size());
    double total = 0;
    if (weight)
        for (int f = 0; f < surface.faceCount(); ++f) cumulative[f] = (total += faceArea(surface, f) * (*weight)[f]);
    else
        for (int f = 0; f < surface.faceCount(); ++f) cumulative[f] = (total += faceArea(surface, f));
    if (!(total > 0)) throw InvalidInputError("the surface has zero area");

    std::mt19937_64 rng(seed);
    std::vector<Vec3> points;
    points.reserve(count);
    for (int s = 0; s < count; ++s) {
        const double pick = unitInterval(rng()) * total;
        const int f = static_cast<int>(std::min<std::ptrdiff_t>(
            std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(), surface.faceCount() - 1));
        points.push_back(randomPointIn(surface, f, rng));
    }
    return points;
}

}  // namespace

std::vector<Vec3> sampleSurfaceUniform(const TriMesh& surface, int count, std::uint64_t seed)
{
    return samplePoints(surface, count, seed, nullptr);
}

std::vector<Vec3> sampleSurface(const TriMesh& surface, int count, std::uint64_t seed, const std::vector<double>& faceDensity)
{
    if (faceDensity.empty()) return samplePoints(surface, count, seed, nullptr);
    if (faceDensity.size() != surface.faces.size())
        throw InvalidInputError("the density has " + std::to_string(faceDensity.size()) + " values for " +
                                std::to_string(surface.faces.size()) + " faces");
    std::vector<double> weight(faceDensity.size());
    for (size_t f = 0; f < weight.size(); ++f) weight[f] = std::sqrt(faceDensity[f]);  // μ_f = sqrt(ρ_f)
    return samplePoints(surface, count, seed, &weight);
}

int topUpSmallComponents(const TriMesh& surface, const std::function<int(const Vec3&)>& faceOf, int minimum, std::uint64_t seed,
                         std::vector<Vec3>& points)
{
    const int faceCount = surface.faceCount();
    DisjointSets sets(static_cast<int>(surface.vertices.size()));
    for (const Face& t : surface.faces) sets.unite(t[0], t[1]), sets.unite(t[0], t[2]);
    const int first = faceCount > 0 ? sets.find(surface.faces[0][0]) : -1;
    bool several = false;
    for (const Face& t : surface.faces) several |= sets.find(t[0]) != first;
    if (!several) return 0;  // one component: only this test is paid
    std::vector<int> pointsIn(surface.vertices.size(), 0);
    std::vector<int> face(points.size());
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < static_cast<long long>(points.size()); ++i) face[size_t(i)] = faceOf(points[size_t(i)]);
    for (int f : face)
        if (f >= 0 && f < faceCount) ++pointsIn[size_t(sets.find(surface.faces[f][0]))];
    // The faces of each component short of points, in the order of their roots.
    std::vector<int> shortIndex(surface.vertices.size(), -1), shortRoot;
    std::vector<std::vector<int>> facesOf;
    for (int f = 0; f < faceCount; ++f) {
        const int root = sets.find(surface.faces[f][0]);
        if (pointsIn[size_t(root)] >= minimum) continue;
        if (shortIndex[size_t(root)] < 0) {
            shortIndex[size_t(root)] = static_cast<int>(facesOf.size());
            shortRoot.push_back(root);
            facesOf.emplace_back();
        }
        facesOf[size_t(shortIndex[size_t(root)])].push_back(f);
    }
    std::vector<size_t> byRoot(facesOf.size());  // the components in the order of their roots
    std::iota(byRoot.begin(), byRoot.end(), size_t(0));
    std::sort(byRoot.begin(), byRoot.end(), [&](size_t a, size_t b) { return shortRoot[a] < shortRoot[b]; });
    std::mt19937_64 rng(seed ^ 0x5bd1e9955bd1e995ULL);
    int added = 0;
    for (size_t c : byRoot) {
        const std::vector<int>& faces = facesOf[c];
        const size_t root = size_t(shortRoot[c]);
        std::vector<double> cumulative(faces.size());
        double total = 0;
        for (size_t k = 0; k < faces.size(); ++k) cumulative[k] = (total += faceArea(surface, faces[k]));
        if (!(total > 0)) continue;
        for (int s = pointsIn[root]; s < minimum; ++s, ++added) {
            const double pick = unitInterval(rng()) * total;
            const size_t k = std::min<size_t>(
                size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()), faces.size() - 1);
            points.push_back(randomPointIn(surface, faces[k], rng));
        }
    }
    return added;
}

}  // namespace fieldcvt
