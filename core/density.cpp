#include "density.h"

#include "curvature.h"
#include "errors.h"
#include "field.h"  // vertexNormals
#include "mesh_edges.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fieldcvt {

std::vector<double> curvatureDensity(const TriMesh& surface, double gradation, double edgeLength)
{
    const int n = surface.vertexCount();
    std::vector<double> mu(n, 1.0);
    if (!(gradation > 0) || n == 0) return mu;
    const PrincipalCurvature k = computePrincipalCurvature(surface, vertexNormals(surface));
    for (int v = 0; v < n; ++v) {
        const double kappa = std::sqrt(k.kMax[v] * k.kMax[v] + k.kMin[v] * k.kMin[v]) * edgeLength;
        const double m = 1 + gradation * (std::isfinite(kappa) ? kappa : 0.0);
        mu[v] = m * m;
    }
    // Clamp: a few noisy or very sharp vertices must not take all the samples.
    const double lowest = *std::min_element(mu.begin(), mu.end());
    for (double& m : mu) m = std::min(m, 25 * lowest);

    // Graded sizing: Laplacian steps (μ ← ½ μ + ½ mean of the neighbours) until the diffusion
    // radius, about ℓ·sqrt(steps / 2) for input edges of mean length ℓ, reaches one target edge.
    // Neighbour lists come out sorted: the table's edges are in (smaller, larger) order.
    const EdgeTable edges = buildEdgeTable(surface);
    std::vector<std::vector<int>> neighbours(n);
    double lengthSum = 0;  // over the faces' sides, as the mean input edge a face sees
    long long sideCount = 0;
    for (int e = 0; e < edges.edgeCount(); ++e) {
        const auto [a, b] = edges.ends[e];
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
        lengthSum += edges.faceCount(e) * (surface.vertices[a] - surface.vertices[b]).norm();
        sideCount += edges.faceCount(e);
    }
    const double meanEdge = sideCount > 0 ? lengthSum / double(sideCount) : edgeLength;
    const double ratio = meanEdge > 0 ? edgeLength / meanEdge : 1.0;
    const int steps = static_cast<int>(std::clamp(std::round(2 * ratio * ratio), 3.0, 50.0));
    std::vector<double> next(n);
    for (int s = 0; s < steps; ++s) {
        for (int v = 0; v < n; ++v) {
            if (neighbours[v].empty()) {
                next[v] = mu[v];
                continue;
            }
            double sum = 0;
            for (int w : neighbours[v]) sum += mu[w];
            next[v] = 0.5 * mu[v] + 0.5 * sum / double(neighbours[v].size());
        }
        mu.swap(next);
    }
    return mu;
}

std::vector<double> densityOnSurface(const std::vector<double>& perInputVertex, const std::vector<int>& cleanIndex,
                                     int surfaceVertexCount)
{
    if (perInputVertex.size() != cleanIndex.size())
        throw InvalidInputError("the vertex density has " + std::to_string(perInputVertex.size()) + " values for " +
                                std::to_string(cleanIndex.size()) + " vertices");
    std::vector<double> sum(surfaceVertexCount, 0.0);
    std::vector<int> count(surfaceVertexCount, 0);
    for (size_t v = 0; v < perInputVertex.size(); ++v) {
        const double mu = perInputVertex[v];
        if (!std::isfinite(mu) || !(mu > 0))
            throw InvalidInputError("the vertex density must be finite and > 0 (vertex " + std::to_string(v) + " has " +
                                    std::to_string(mu) + ")");
        const int s = cleanIndex[v];
        if (s >= 0 && s < surfaceVertexCount) sum[s] += mu, ++count[s];
    }
    for (int s = 0; s < surfaceVertexCount; ++s) sum[s] = count[s] > 0 ? sum[s] / count[s] : 1.0;
    return sum;
}

void normaliseDensity(const TriMesh& surface, std::vector<double>& mu)
{
    double weighted = 0, area = 0;
    for (int f = 0; f < surface.faceCount(); ++f) {
        const Face& t = surface.faces[f];
        const double a = faceArea(surface, f);
        weighted += a * (mu[t[0]] + mu[t[1]] + mu[t[2]]) / 3.0;
        area += a;
    }
    if (!(weighted > 0) || !std::isfinite(weighted)) throw InvalidInputError("the vertex density integrates to zero");
    const double factor = area / weighted;
    for (double& m : mu) m *= factor;
}

std::vector<double> faceDensity(const TriMesh& surface, const std::vector<double>& mu)
{
    std::vector<double> rho;
    if (mu.empty()) return rho;
    rho.resize(surface.faces.size());
    for (size_t f = 0; f < surface.faces.size(); ++f) {
        const Face& t = surface.faces[f];
        rho[f] = (mu[t[0]] * mu[t[0]] + mu[t[1]] * mu[t[1]] + mu[t[2]] * mu[t[2]]) / 3.0;
    }
    return rho;
}

}  // namespace fieldcvt
