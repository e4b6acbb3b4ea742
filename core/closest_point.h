#pragma once
// Exact closest-point queries on a triangle mesh through an axis-aligned bounding-box tree.
// Used to project samples on the input surface (RDT output vertices, field interpolation) and
// for the d_RMS / d_H metrics.
#include "mesh.h"

#include <memory>
#include <vector>

namespace fieldcvt {

struct ClosestPoint {
    Vec3 point;        //!< closest point on the surface
    int face = -1;     //!< face containing it
    Vec3 barycentric;  //!< its barycentric coordinates in that face (sum 1)
    double squaredDistance = 0;
};

//! Closest point on triangle (a, b, c) to p; also returns barycentric coordinates.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3* barycentric = nullptr);

class ClosestPointTree {
public:
    //! Builds the tree; the mesh must outlive the tree.
    explicit ClosestPointTree(const TriMesh& mesh);
    ~ClosestPointTree();
    ClosestPointTree(const ClosestPointTree&) = delete;
    ClosestPointTree& operator=(const ClosestPointTree&) = delete;

    //! Exact closest point; thread-safe (const, no allocation).
    ClosestPoint closest(const Vec3& p) const;

    //! The same answer, faster when `hintFace` is near the answer (e.g. the previous answer for a
    //! point that moved a little): its distance bounds the search from the start. Ties still go
    //! to the lowest face index, so the result does not depend on the hint. A hint out of range
    //! (e.g. -1) is ignored.
    ClosestPoint closest(const Vec3& p, int hintFace) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! Upper bounds of the distance from a point to a triangle mesh, without the tree: a short walk
//! over the faces from one near the answer (e.g. a vertex's closest face), to the face across
//! the edge the closest point lies on, or to the nearest face around the corner it lies on,
//! while that gets nearer. Every face
//! visited holds a surface point, so the result is never below the exact distance, and on a
//! surface that is locally a graph it is the exact one (bit for bit: the same triangle test as
//! ClosestPointTree). For checks that only compare a distance with a limit: a bound under the
//! limit answers them without the tree query (several times the cost).
class SurfaceWalk {
public:
    //! The mesh must outlive the walk.
    explicit SurfaceWalk(const TriMesh& mesh);
    //! A distance from p to the mesh that is at least the exact one; +infinity when `startFace`
    //! is out of range. `endFace` (if given) receives the face the walk ended on (unchanged when
    //! `startFace` is out of range): the start for the next query of a point that moved a
    //! little. Thread-safe.
    double distanceBound(const Vec3& p, int startFace, int* endFace = nullptr) const;
    //! The walk's answer itself: the nearest point of the last face reached (face -1 when
    //! `startFace` is out of range or p is not finite). `settled` (if given) tells whether the
    //! walk stopped at a local minimum (no neighbouring face nearer) rather than at its step limit.
    //! The walk stops in the first face that holds p's projection; `throughFaces` also compares
    //! such a face with the three across its edges (nearer where the surface is concave), so
    //! that it stops only at a local minimum over faces.
    ClosestPoint closestFrom(const Vec3& p, int startFace, bool* settled = nullptr, bool throughFaces = false) const;

private:
    const TriMesh& mesh_;
    std::vector<int> across_;          //!< per half-edge 3 f + k: the face across it, -1 on a border or non-manifold edge
    std::vector<int> fanFirst_, fan_;  //!< CSR: the faces around each vertex
};

}  // namespace fieldcvt
