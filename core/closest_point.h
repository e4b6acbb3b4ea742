#pragma once
// Exact closest-point queries on a triangle mesh through an axis-aligned bounding-box tree.
// Used to project samples on the input surface (RDT output vertices, field interpolation) and
// for the d_RMS / d_H metrics.
#include "mesh.h"

#include <memory>
#include <vector>

namespace fieldcvt {

struct ClosestPoint {
    Vec3 point;            //!< closest point on the surface
    int face = -1;         //!< face containing it
    Vec3 barycentric;      //!< its barycentric coordinates in that face (sum 1)
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

}  // namespace fieldcvt
