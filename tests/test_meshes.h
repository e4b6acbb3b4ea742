#pragma once
// Small procedural meshes for unit tests, and the path of the bundled ones.
#include "errors.h"
#include "mesh.h"
#include "mesh_check.h"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace fieldcvt::testmesh {

inline std::string resource(const std::string& name) { return std::string(FCVT_RESOURCES_DIR) + "/" + name; }

//! The strict input check's refusal of `mesh` (prepareInput's message), "" if it passes.
inline std::string inputError(const TriMesh& mesh)
{
    InputReport report;
    try {
        prepareInput(mesh, report);
    } catch (const InvalidInputError& e) {
        return e.what();
    }
    return "";
}

//! A Moebius band (the one of tests/robustness/meshgen.py): n quads between two rails; vertex 2i
//! is the -width rail, 2i + 1 the +width rail, and after a full turn the rails swap.
inline TriMesh moebius(int n = 24, double width = 0.3)
{
    const double pi = 3.14159265358979323846;
    TriMesh m;
    for (int i = 0; i < n; ++i) {
        const double u = 2 * pi * i / n;
        for (double s : {-width, width})
            m.vertices.emplace_back((1 + s * std::cos(u / 2)) * std::cos(u), (1 + s * std::cos(u / 2)) * std::sin(u),
                                    s * std::sin(u / 2));
    }
    for (int i = 0; i < n; ++i) {
        const int a = 2 * i, b = 2 * i + 1;
        const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
        m.faces.push_back({a, c, d});
        m.faces.push_back({a, d, b});
    }
    return m;
}

//! Planar grid over [0, size]^2 (z = 0), `cells` x `cells` squares split into two triangles.
inline TriMesh planeGrid(int cells, double size = 1.0)
{
    TriMesh m;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) m.vertices.emplace_back(size * i / cells, size * j / cells, 0.0);
    auto id = [cells](int i, int j) { return j * (cells + 1) + i; };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

//! Torus with major radius R, minor radius r, n x m quads split into triangles (genus 1).
inline TriMesh torus(int n, int m, double R = 1.0, double r = 0.35)
{
    TriMesh t;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * pi * i / n, v = 2 * pi * j / m;
            t.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    auto id = [n, m](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return t;
}

//! Unit disk in the plane z = 0: a centre vertex and `rings` rings of 6k vertices (no corners
//! on its border, unlike planeGrid).
inline TriMesh disk(int rings)
{
    const double pi = 3.14159265358979323846;
    TriMesh m;
    m.vertices.emplace_back(0, 0, 0);
    for (int r = 1; r <= rings; ++r)
        for (int k = 0; k < 6 * r; ++k) {
            const double a = 2 * pi * k / (6 * r);
            m.vertices.emplace_back(std::cos(a) * r / rings, std::sin(a) * r / rings, 0.0);
        }
    auto ringStart = [](int r) { return r == 0 ? 0 : 1 + 3 * r * (r - 1); };
    for (int r = 1; r <= rings; ++r) {
        // Walk the outer ring r and the inner ring r - 1 together, always advancing the one
        // whose next vertex comes first in angle (the centre is a ring of one).
        const int nOut = 6 * r, nIn = r == 1 ? 1 : 6 * (r - 1);
        int i = 0, o = 0;
        while (o < nOut || (nIn > 1 && i < nIn)) {
            const int in0 = ringStart(r - 1) + i % nIn, out0 = ringStart(r) + o % nOut;
            const bool advanceOuter = nIn == 1 || i >= nIn || (o < nOut && (o + 1.0) / nOut <= (i + 1.0) / nIn);
            if (advanceOuter) {
                m.faces.push_back({in0, out0, ringStart(r) + (o + 1) % nOut});
                ++o;
            } else {
                m.faces.push_back({in0, out0, ringStart(r - 1) + (i + 1) % nIn});
                ++i;
            }
        }
    }
    return m;
}

//! A closed thin box [0, 1] x [0, thickness] x [0, 1] (a plate: top at y = thickness, bottom
//! at y = 0), `cells` x `cells` squares on top and bottom, one row of them on each side wall;
//! outward orientation.
inline TriMesh thinBox(int cells, double thickness)
{
    TriMesh m;
    std::map<std::array<long long, 3>, int> index;
    auto vertex = [&](double x, double y, double z) {
        const std::array<long long, 3> key{std::llround(x * 1e9), std::llround(y * 1e9), std::llround(z * 1e9)};
        auto [it, added] = index.emplace(key, static_cast<int>(m.vertices.size()));
        if (added) m.vertices.emplace_back(x, y, z);
        return it->second;
    };
    // A quad a-b-c-d, counter-clockwise seen from outside.
    auto quad = [&](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
        const int ia = vertex(a.x(), a.y(), a.z()), ib = vertex(b.x(), b.y(), b.z());
        const int ic = vertex(c.x(), c.y(), c.z()), id = vertex(d.x(), d.y(), d.z());
        m.faces.push_back({ia, ib, ic});
        m.faces.push_back({ia, ic, id});
    };
    const double t = thickness;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const double x0 = double(i) / cells, x1 = double(i + 1) / cells, z0 = double(j) / cells, z1 = double(j + 1) / cells;
            quad({x0, t, z0}, {x0, t, z1}, {x1, t, z1}, {x1, t, z0});  // top, +y
            quad({x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, {x0, 0, z1});  // bottom, -y
        }
    for (int k = 0; k < cells; ++k) {
        const double s0 = double(k) / cells, s1 = double(k + 1) / cells;
        quad({s0, 0, 0}, {s0, t, 0}, {s1, t, 0}, {s1, 0, 0});  // z = 0, -z
        quad({s0, 0, 1}, {s1, 0, 1}, {s1, t, 1}, {s0, t, 1});  // z = 1, +z
        quad({0, 0, s0}, {0, 0, s1}, {0, t, s1}, {0, t, s0});  // x = 0, -x
        quad({1, 0, s0}, {1, t, s0}, {1, t, s1}, {1, 0, s1});  // x = 1, +x
    }
    return m;
}

//! thinBox(8, thickness / size) scaled by `size`: a size x thickness x size plate.
inline TriMesh scaledThinBox(double size, double thickness)
{
    TriMesh m = thinBox(8, thickness / size);
    for (Vec3& v : m.vertices) v *= size;
    return m;
}

//! Unit icosphere subdivided `levels` times (closed, genus 0, outward orientation).
inline TriMesh icosphere(int levels)
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    TriMesh m;
    m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3& v : m.vertices) v.normalize();
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
            return mid[key] = m.vertexCount() - 1;
        };
        std::vector<Face> faces;
        for (const Face& f : m.faces) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            faces.push_back({f[0], ab, ca});
            faces.push_back({f[1], bc, ab});
            faces.push_back({f[2], ca, bc});
            faces.push_back({ab, bc, ca});
        }
        m.faces = std::move(faces);
    }
    return m;
}

}  // namespace fieldcvt::testmesh
