#include "triangulate.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <utility>

namespace fieldcvt {

namespace {

// Exact orientation tests (filtered: doubles where they decide, exact arithmetic where not).
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;

bool leftTurn(const Point2& a, const Point2& b, const Point2& c) { return CGAL::orientation(a, b, c) == CGAL::LEFT_TURN; }
bool rightTurn(const Point2& a, const Point2& b, const Point2& c) { return CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN; }

//! How much the corner b turns left, relative to its edges: sin of the turn, 0 when straight
//! (a ranking, not a decision: the decisions are the exact tests above).
double turn(const Point2& a, const Point2& b, const Point2& c)
{
    const double abx = b.x() - a.x(), aby = b.y() - a.y(), bcx = c.x() - b.x(), bcy = c.y() - b.y();
    const double lengths = std::hypot(abx, aby) * std::hypot(bcx, bcy);
    return lengths > 0 ? (abx * bcy - aby * bcx) / lengths : 0.0;
}

// Corners turning less than this (sine of the angle) count as straight while another ear exists.
constexpr double kStraight = 1e-12;

bool isZeroArea(const TriMesh& mesh, const Face& t)
{
    int exponent = 0;
    return (scaledCross(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], exponent).array() == 0.0).all();
}

//! The polygon in the plane of its Newell normal, counter-clockwise; empty when it has no plane
//! (all corners on a line, or a corner not finite).
//! Relative to the first corner and scaled by a power of two (exact): no overflow at 1e300, and
//! dropping an axis is exact, so the exact tests decide for the projected polygon itself.
std::vector<Point2> projectToPlane(const std::vector<Vec3>& points, const std::vector<int>& corners)
{
    const int n = static_cast<int>(corners.size());
    // A non-finite corner has no plane: the exact predicates below would run without end on it
    // (fuzz_read_mesh: a PLY quad with a -inf corner, before the reader refused the vertex).
    for (int c : corners)
        if (!points[c].allFinite()) return {};
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
    if (!(std::abs(normal[axis]) > 0)) return {};
    // The plane of the two other axes, ordered so that the polygon runs counter-clockwise.
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0) std::swap(u, v);
    std::vector<Point2> p;
    p.reserve(n);
    for (int i = 0; i < n; ++i) p.emplace_back(local[i][u], local[i][v]);
    return p;
}

//! Whether the closed polyline is simple: no repeated point, no two edges meeting but at their
//! shared corner, no edge folding back over the previous one. Exact; O(n^2), for small polygons.
bool isSimplePolygon(const std::vector<Point2>& p)
{
    const int n = static_cast<int>(p.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (p[i] == p[j]) return false;
    for (int i = 0; i < n; ++i) {
        const Point2 &a = p[i], &b = p[(i + 1) % n];
        const Point2& next = p[(i + 2) % n];
        // b -> next goes back along a -> b: collinear, and next on b's side towards a.
        if (CGAL::collinear(a, b, next) && !CGAL::collinear_are_ordered_along_line(a, b, next)) return false;
        for (int j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through corner 0
            if (CGAL::do_intersect(Kernel::Segment_2(a, b), Kernel::Segment_2(p[j], p[(j + 1) % n]))) return false;
        }
    }
    return true;
}

//! Ear clipping over `left` (positions in p / corners). An ear is a corner that turns left
//! (first more than kStraight, then at all) whose triangle holds no other corner, not even on
//! its new diagonal; without one (not simple), the corner that turns most, then a fan.
void clipEars(const std::vector<Point2>& p, const std::vector<int>& corners, std::vector<Face>& faces)
{
    const int n = static_cast<int>(p.size());
    std::vector<int> left(n);
    for (int i = 0; i < n; ++i) left[i] = i;
    auto isEar = [&](int prev, int cur, int next, bool strict) {
        if (!leftTurn(p[prev], p[cur], p[next])) return false;
        if (strict && !(turn(p[prev], p[cur], p[next]) > kStraight)) return false;
        for (int r : left) {
            if (r == prev || r == cur || r == next || p[r] == p[prev] || p[r] == p[cur] || p[r] == p[next]) continue;
            if (!rightTurn(p[prev], p[cur], p[r]) && !rightTurn(p[cur], p[next], p[r]) && !rightTurn(p[next], p[prev], p[r]))
                return false;  // inside the ear, or on its new diagonal
        }
        return true;
    };
    while (left.size() > 3) {
        const int m = static_cast<int>(left.size());
        int chosen = -1;
        for (bool strict : {true, false})
            for (int step = 1; step <= m && chosen < 0; ++step) {  // from the second corner on
                const int i = step % m;
                if (isEar(left[(i + m - 1) % m], left[i], left[(i + 1) % m], strict)) chosen = i;
            }
        if (chosen < 0) {  // not simple: the corner that turns most, if any does
            double best = kStraight;
            for (int i = 0; i < m; ++i) {
                const double t = turn(p[left[(i + m - 1) % m]], p[left[i]], p[left[(i + 1) % m]]);
                if (t > best) best = t, chosen = i;
            }
            if (chosen < 0) break;
        }
        faces.push_back({corners[left[(chosen + m - 1) % m]], corners[left[chosen]], corners[left[(chosen + 1) % m]]});
        left.erase(left.begin() + chosen);
    }
    for (std::size_t i = 1; i + 1 < left.size(); ++i) faces.push_back({corners[left[0]], corners[left[i]], corners[left[i + 1]]});
}

//! The constrained Delaunay triangulation of a simple polygon (its edges the constraints, the
//! faces inside them kept), appended to `faces`; false, appending nothing, when the polygon turns
//! out not to be simple (repeated points, crossing or touching edges).
bool triangulateByCdt(const std::vector<Point2>& p, const std::vector<int>& corners, std::vector<Face>& faces)
{
    struct Inside {
        int nesting = -1;  // constrained edges crossed from the outside; odd = inside
    };
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
    using Fbb = CGAL::Triangulation_face_base_with_info_2<Inside, Kernel>;
    using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbb>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
    const int n = static_cast<int>(p.size());
    try {
        std::vector<std::pair<Point2, int>> located(n);
        for (int i = 0; i < n; ++i) located[i] = {p[i], i};
        Cdt cdt;
        cdt.insert(located.begin(), located.end());
        if (static_cast<int>(cdt.number_of_vertices()) != n) return false;  // repeated points
        std::vector<Cdt::Vertex_handle> vertex(n);
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vertex[v->info()] = v;
        for (int i = 0; i < n; ++i) cdt.insert_constraint(vertex[i], vertex[(i + 1) % n]);
        for (int i = 0; i < n; ++i)
            if (!cdt.is_edge(vertex[i], vertex[(i + 1) % n])) return false;  // a corner on another edge
        // Nesting by a walk from the outside that counts the constraints it crosses.
        std::vector<Cdt::Face_handle> queue{cdt.infinite_face()};
        cdt.infinite_face()->info().nesting = 0;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const Cdt::Face_handle f = queue[head];
            for (int e = 0; e < 3; ++e) {
                const Cdt::Face_handle g = f->neighbor(e);
                if (g->info().nesting >= 0) continue;
                g->info().nesting = f->info().nesting + (cdt.is_constrained({f, e}) ? 1 : 0);
                queue.push_back(g);
            }
        }
        std::vector<Face> inside;
        inside.reserve(n - 2);
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
            if (f->info().nesting % 2 == 1)  // counter-clockwise in the plane: the polygon's orientation
                inside.push_back({corners[f->vertex(0)->info()], corners[f->vertex(1)->info()], corners[f->vertex(2)->info()]});
        if (static_cast<int>(inside.size()) != n - 2) return false;
        faces.insert(faces.end(), inside.begin(), inside.end());
        return true;
    } catch (const std::exception&) {  // crossing constraints (No_constraint_intersection_tag)
        return false;
    }
}

}  // namespace

PolygonShape triangulatePolygon(const std::vector<Vec3>& points, const std::vector<int>& corners, std::vector<Face>& faces)
{
    const int n = static_cast<int>(corners.size());
    if (n == 3) {  // a triangle as it is (most faces of most files), without the work lists below
        faces.push_back({corners[0], corners[1], corners[2]});
        return PolygonShape::Simple;
    }
    auto fan = [&] {
        for (int i = 1; i + 1 < n; ++i) faces.push_back({corners[0], corners[i], corners[i + 1]});
    };
    if (n < 3) return PolygonShape::NotSimple;
    const std::vector<Point2> p = projectToPlane(points, corners);
    if (p.empty()) {  // no plane: nothing better than a fan
        fan();
        return PolygonShape::NotSimple;
    }
    if (n > kMaxEarClippingCorners) {
        if (triangulateByCdt(p, corners, faces)) return PolygonShape::Simple;
        // Not simple: ear clipping's best effort while it stays affordable.
        constexpr int kMaxBestEffortCorners = 4096;
        if (n <= kMaxBestEffortCorners)
            clipEars(p, corners, faces);
        else
            fan();
        return PolygonShape::NotSimple;
    }
    const bool simple = isSimplePolygon(p);
    clipEars(p, corners, faces);
    return simple ? PolygonShape::Simple : PolygonShape::NotSimple;
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
