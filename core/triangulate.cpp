#include "triangulate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace fieldcvt {

namespace {

using Point2 = Eigen::Vector2d;

double orient(const Point2& a, const Point2& b, const Point2& c)
{
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

//! How much the corner b turns left, relative to its edges: sin of the turn, 0 when straight.
double turn(const Point2& a, const Point2& b, const Point2& c)
{
    const double lengths = (b - a).norm() * (c - b).norm();
    return lengths > 0 ? orient(a, b, c) / lengths : 0.0;
}

// Corners turning less than this (sine of the angle) count as straight.
constexpr double kStraight = 1e-12;

bool isZeroArea(const TriMesh& mesh, const Face& t)
{
    int exponent = 0;
    return (scaledCross(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], exponent).array() == 0.0).all();
}

}  // namespace

void triangulatePolygon(const std::vector<Vec3>& points, const std::vector<int>& corners, std::vector<Face>& faces)
{
    const int n = static_cast<int>(corners.size());
    if (n == 3) {  // a triangle as it is (most faces of most files), without the work lists below
        faces.push_back({corners[0], corners[1], corners[2]});
        return;
    }
    auto fan = [&](const std::vector<int>& order) {
        for (std::size_t i = 1; i + 1 < order.size(); ++i) faces.push_back({corners[order[0]], corners[order[i]], corners[order[i + 1]]});
    };
    std::vector<int> left(n);
    for (int i = 0; i < n; ++i) left[i] = i;
    if (n <= 3 || n > kMaxEarClippingCorners) return fan(left);

    // Corners relative to the first, scaled by a power of two (exact): no overflow at 1e300.
    const Vec3& origin = points[corners[0]];
    double extent = 0;
    for (int c : corners) extent = std::max(extent, (points[c] - origin).cwiseAbs().maxCoeff());
    int k = 0;
    if (extent > 0 && std::isfinite(extent)) std::frexp(extent, &k);
    std::vector<Vec3> local(n);
    for (int i = 0; i < n; ++i) {
        const Vec3 d = points[corners[i]] - origin;
        local[i] = Vec3(std::ldexp(d.x(), -k), std::ldexp(d.y(), -k), std::ldexp(d.z(), -k));
    }
    Vec3 normal = Vec3::Zero();  // Newell's normal
    for (int i = 0; i < n; ++i) normal += local[i].cross(local[(i + 1) % n]);
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    if (!(std::abs(normal[axis]) > 0)) return fan(left);  // no plane: nothing better than a fan
    // The plane of the two other axes, ordered so that the polygon runs counter-clockwise.
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0) std::swap(u, v);
    std::vector<Point2> p(n);
    for (int i = 0; i < n; ++i) p[i] = Point2(local[i][u], local[i][v]);

    auto isEar = [&](int prev, int cur, int next) {
        if (!(turn(p[prev], p[cur], p[next]) > kStraight)) return false;
        for (int r : left) {
            if (r == prev || r == cur || r == next || p[r] == p[prev] || p[r] == p[cur] || p[r] == p[next]) continue;
            if (orient(p[prev], p[cur], p[r]) >= 0 && orient(p[cur], p[next], p[r]) >= 0 && orient(p[next], p[prev], p[r]) >= 0)
                return false;  // inside the ear, or on its new diagonal
        }
        return true;
    };
    while (left.size() > 3) {
        const int m = static_cast<int>(left.size());
        int chosen = -1;
        for (int step = 1; step <= m && chosen < 0; ++step) {  // from the second corner on
            const int i = step % m;
            if (isEar(left[(i + m - 1) % m], left[i], left[(i + 1) % m])) chosen = i;
        }
        if (chosen < 0) {  // flat or self-intersecting: the corner that turns most, if any does
            double best = kStraight;
            for (int i = 0; i < m; ++i) {
                const double t = turn(p[left[(i + m - 1) % m]], p[left[i]], p[left[(i + 1) % m]]);
                if (t > best) best = t, chosen = i;
            }
            if (chosen < 0) return fan(left);
        }
        faces.push_back({corners[left[(chosen + m - 1) % m]], corners[left[chosen]], corners[left[(chosen + 1) % m]]});
        left.erase(left.begin() + chosen);
    }
    fan(left);
}

int flipZeroAreaTriangles(TriMesh& mesh)
{
    std::vector<int> candidates;
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const Face& t = mesh.faces[f];
        if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0] && isZeroArea(mesh, t)) candidates.push_back(f);
    }
    int flipped = 0;
    // Each pass flips the candidates whose neighbour no earlier flip of the pass touched; a
    // flip can make the next one possible (a run of straight corners), so passes repeat until
    // none succeeds.
    for (bool progress = !candidates.empty(); progress;) {
        progress = false;
        using Edge = std::pair<int, int>;
        auto edgeOf = [](int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; };
        std::map<Edge, std::vector<int>> facesOf;
        for (int f = 0; f < mesh.faceCount(); ++f)
            for (int j = 0; j < 3; ++j) facesOf[edgeOf(mesh.faces[f][j], mesh.faces[f][(j + 1) % 3])].push_back(f);
        std::vector<char> touched(mesh.faces.size(), 0);
        std::vector<int> remaining;
        for (int f : candidates) {
            const Face t = mesh.faces[f];
            // The middle corner is the one opposite the longest edge.
            int mid = 0;
            double longest = -1;
            for (int j = 0; j < 3; ++j) {
                const double len = (mesh.vertices[t[(j + 1) % 3]] - mesh.vertices[t[(j + 2) % 3]]).cwiseAbs().maxCoeff();
                if (len > longest) longest = len, mid = j;
            }
            const int b = t[mid], a = t[(mid + 1) % 3], c = t[(mid + 2) % 3];
            const Vec3& pb = mesh.vertices[b];
            // The neighbour: the one face of non-zero area on a-c, or, when an adjacent polygon's
            // fan put a zero-area triangle on the same edge, the one running c -> a (t runs a -> c).
            int other = -1;
            const auto on = facesOf.find(edgeOf(a, c));
            if (!touched[f] && pb != mesh.vertices[a] && pb != mesh.vertices[c] && on != facesOf.end()) {
                std::vector<int> any, opposite;
                for (int g : on->second) {
                    if (g == f || isZeroArea(mesh, mesh.faces[g])) continue;
                    any.push_back(g);
                    const Face& u = mesh.faces[g];
                    for (int j = 0; j < 3; ++j)
                        if (u[j] == c && u[(j + 1) % 3] == a) opposite.push_back(g);
                }
                other = opposite.size() == 1 ? opposite[0] : any.size() == 1 ? any[0] : -1;
            }
            if (other < 0 || touched[other]) {
                remaining.push_back(f);
                continue;
            }
            const Face u = mesh.faces[other];
            int x = 0;  // u runs x -> y along the shared edge
            while (!((u[x] == a || u[x] == c) && (u[(x + 1) % 3] == a || u[(x + 1) % 3] == c))) ++x;
            const int from = u[x], to = u[(x + 1) % 3], d = u[(x + 2) % 3];
            if (d == b || facesOf.count(edgeOf(b, d))) {
                remaining.push_back(f);
                continue;
            }
            mesh.faces[f] = {from, b, d};
            mesh.faces[other] = {b, to, d};
            touched[f] = touched[other] = 1;
            ++flipped;
            progress = true;
        }
        candidates.swap(remaining);
    }
    return flipped;
}

}  // namespace fieldcvt
