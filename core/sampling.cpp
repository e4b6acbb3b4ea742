#include "sampling.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace fieldcvt {

namespace {

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
        // Uniform point in a triangle: sqrt maps the first coordinate so density is constant.
        const double r1 = std::sqrt(unitInterval(rng())), r2 = unitInterval(rng());
        const Face& t = surface.faces[f];
        points.push_back((1 - r1) * surface.vertices[t[0]] + r1 * (1 - r2) * surface.vertices[t[1]] +
                         r1 * r2 * surface.vertices[t[2]]);
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

}  // namespace fieldcvt
