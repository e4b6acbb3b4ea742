#include "valence_colour.h"

#include <algorithm>
#include <array>
#include <utility>

namespace fcvt_plugin {

ValenceColouring colourByValence(const fieldcvt::TriMesh& mesh)
{
    // Undirected edges with the number of faces on each.
    std::vector<std::pair<int, int>> halfEdges;
    halfEdges.reserve(mesh.faces.size() * 3);
    for (const fieldcvt::Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) halfEdges.emplace_back(std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3]));
    std::sort(halfEdges.begin(), halfEdges.end());

    const size_t n = mesh.vertices.size();
    std::vector<int> valence(n, 0);
    std::vector<char> onBoundary(n, 0);
    for (size_t i = 0; i < halfEdges.size();) {
        size_t j = i;
        while (j < halfEdges.size() && halfEdges[j] == halfEdges[i]) ++j;
        const auto [a, b] = halfEdges[i];
        if (a != b && a >= 0 && b >= 0 && size_t(a) < n && size_t(b) < n) {
            ++valence[size_t(a)];
            ++valence[size_t(b)];
            if (j - i == 1) onBoundary[size_t(a)] = onBoundary[size_t(b)] = 1;
        }
        i = j;
    }

    ValenceColouring out;
    out.colours.resize(n);
    for (size_t v = 0; v < n; ++v) {
        if (valence[v] == 0) {
            out.colours[v] = kValenceUnused;
            ++out.unused;
            continue;
        }
        const int target = onBoundary[v] ? 4 : 6;
        int& low = onBoundary[v] ? out.boundaryLow : out.interiorLow;
        int& regular = onBoundary[v] ? out.boundaryRegular : out.interiorRegular;
        int& high = onBoundary[v] ? out.boundaryHigh : out.interiorHigh;
        if (valence[v] < target) {
            out.colours[v] = kValenceLow;
            ++low;
        } else if (valence[v] > target) {
            out.colours[v] = kValenceHigh;
            ++high;
        } else {
            out.colours[v] = kValenceRegular;
            ++regular;
        }
    }
    return out;
}

}  // namespace fcvt_plugin
