#include "part_coverage.h"

#include "closest_point.h"
#include "mesh_edges.h"
#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace fieldcvt {

namespace {

struct Sample {
    Vec3 point;
    int part;  //!< the input component
};

//! The centroids of the n x n subdivision of every face (n from its longest edge and `spacing`,
//! at most 32), plus every vertex (so that the gap sees the corners).
std::vector<Sample> sampleFaces(const TriMesh& mesh, const std::vector<int>& component, double spacing)
{
    std::vector<Sample> samples;
    std::vector<char> emitted(mesh.vertexCount(), 0);
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        for (int v : t)
            if (!emitted[v]) {
                emitted[v] = 1;
                samples.push_back({mesh.vertices[v], component[f]});
            }
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 32);
        const Vec3 u = (b - a) / n, w = (c - a) / n;
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                samples.push_back({a + (i + 1.0 / 3) * u + (j + 1.0 / 3) * w, component[f]});
                if (i + j < n - 1) samples.push_back({a + (i + 2.0 / 3) * u + (j + 2.0 / 3) * w, component[f]});
            }
    }
    return samples;
}

//! Per input component, the output components it owns: an output component belongs to the
//! input component nearest to most of its vertices (ties to the lower index). Parts that touch
//! or cross each other do not confuse this, as nearest output pieces to a part's points would.
std::vector<int> piecesPerPart(const TriMesh& output, const std::vector<int>& outputPiece, int outputComponents,
                               const TriMesh& input, const std::vector<int>& inputPart, int inputComponents)
{
    std::vector<int> pieces(inputComponents, 0);
    if (output.faceCount() == 0 || input.faceCount() == 0) return pieces;
    std::vector<int> vertexPiece(output.vertexCount(), -1);
    for (int f = 0; f < output.faceCount(); ++f)
        for (int v : output.faces[f]) vertexPiece[v] = outputPiece[f];
    std::vector<int> nearestPart(output.vertexCount(), -1);
    const ClosestPointTree tree(input);
#pragma omp parallel for schedule(static)
    for (int v = 0; v < output.vertexCount(); ++v)
        if (vertexPiece[v] >= 0) nearestPart[v] = inputPart[tree.closest(output.vertices[v]).face];
    std::vector<std::map<int, int>> votes(outputComponents);
    for (int v = 0; v < output.vertexCount(); ++v)
        if (vertexPiece[v] >= 0) ++votes[vertexPiece[v]][nearestPart[v]];
    for (const auto& vote : votes) {
        int owner = -1, most = 0;
        for (const auto& [part, count] : vote)
            if (count > most) owner = part, most = count;
        if (owner >= 0) ++pieces[owner];
    }
    return pieces;
}

}  // namespace

PartCoverage measurePartCoverage(const TriMesh& output, const TriMesh& input, const PartCoverageParams& params)
{
    int inputComponents = 0, outputComponents = 0;
    const std::vector<int> inputPart =
        faceComponents(buildEdgeTable(input, RepeatedVertexFaces::Skip), input.faceCount(), inputComponents);
    const std::vector<int> outputPiece =
        faceComponents(buildEdgeTable(output, RepeatedVertexFaces::Skip), output.faceCount(), outputComponents);

    std::vector<double> area(inputComponents, 0.0);
    double totalArea = 0;
    for (int f = 0; f < input.faceCount(); ++f) {
        const Face& t = input.faces[f];
        const double a =
            0.5 * (input.vertices[t[1]] - input.vertices[t[0]]).cross(input.vertices[t[2]] - input.vertices[t[0]]).norm();
        area[inputPart[f]] += a;
        totalArea += a;
    }
    const double edgeLength = meanEdgeLength(output);
    const bool noOutput = output.faceCount() == 0 || !(edgeLength > 0);
    const double spacing = noOutput ? std::numeric_limits<double>::infinity() : 0.5 * edgeLength;
    const std::vector<Sample> samples = sampleFaces(input, inputPart, spacing);

    // Per sample: distance to the output and the output component it is nearest to.
    std::vector<double> distance(samples.size(), std::numeric_limits<double>::infinity());
    if (!noOutput) {
        const ClosestPointTree tree(output);
#pragma omp parallel for schedule(static)
        for (long long i = 0; i < static_cast<long long>(samples.size()); ++i) {
            const ClosestPoint c = tree.closest(samples[i].point);
            distance[i] = std::sqrt(c.squaredDistance);
        }
    }

    std::vector<double> gap(inputComponents, 0.0);
    std::vector<Vec3> farthest(inputComponents, Vec3::Zero());
    for (size_t i = 0; i < samples.size(); ++i)
        if (distance[i] > gap[samples[i].part]) {
            gap[samples[i].part] = distance[i];
            farthest[samples[i].part] = samples[i].point;
        }
    const std::vector<int> pieces = piecesPerPart(output, outputPiece, outputComponents, input, inputPart, inputComponents);
    PartCoverage coverage;
    for (int p = 0; p < inputComponents; ++p) {
        const double fraction = totalArea > 0 ? area[p] / totalArea : 0.0;
        if (fraction < params.minAreaFraction) {
            ++coverage.smallParts;
            coverage.smallAreaFraction += fraction;
            coverage.smallPartsGap = std::max(coverage.smallPartsGap, noOutput ? gap[p] : gap[p] / edgeLength);
            continue;
        }
        PartFigures figures;
        figures.areaFraction = fraction;
        figures.gap = noOutput ? std::numeric_limits<double>::infinity() : gap[p] / edgeLength;
        figures.pieces = pieces[p];
        figures.farthestPoint = farthest[p];
        coverage.parts.push_back(figures);
        coverage.largestGap = std::max(coverage.largestGap, figures.gap);
        coverage.mostPieces = std::max(coverage.mostPieces, figures.pieces);
    }
    std::stable_sort(coverage.parts.begin(), coverage.parts.end(),
                     [](const PartFigures& x, const PartFigures& y) { return x.areaFraction > y.areaFraction; });
    return coverage;
}

}  // namespace fieldcvt
