#pragma once
// The input surface as local_remesh.cpp queries it: closest points on a vertex's own sheet (a
// walk over the faces, the tree where the walk does not settle), the open border loops and the
// feature lines as curves that border and feature vertices slide along, the target edge length.
// Internal to the core.
#include "closest_point.h"
#include "mesh.h"
#include "strip_sizing.h"
#include "valence/surface.h"

#include <algorithm>
#include <array>
#include <vector>

namespace fieldcvt::local_remesh_detail {

//! Throws InvalidInputError for a face mask of the wrong size, or selected faces with an index
//! out of range, a repeated or non-finite vertex, or that are not a manifold, oriented surface.
void checkSelection(const TriMesh& surface, const std::vector<char>& selectedFaces);

//! A place on the surface: the point, its face and (on a border loop or a feature line) the
//! curve edge it lies on.
struct Spot {
    Vec3 point = Vec3::Zero();
    int face = -1;
    int curve = -1;
};

//! A border or feature edge of the surface.
struct CurveEdge {
    int u, v;  //!< surface vertices
    int face;  //!< a selected face that has the edge
    bool border;
};

//! Where a vertex of the mesh being remeshed is on the surface, and what it may do there.
struct VertexInfo {
    VertexRole role = VertexRole::Free;
    bool onBorder = false;  //!< on an open border loop (Boundary, or a Corner there)
    int face = -1;          //!< surface face of its closest point
    int curve = -1;         //!< Boundary / Feature: the surface curve edge it lies on
    int corner = -1;        //!< Corner: its surface vertex
    int component = -1;     //!< its surface component
    double target = 0;      //!< the target edge length where it is (Surface::targetAt)
};

//! The selected faces as the remeshing starts from them, on the surface vertices they use (in
//! index order).
struct StartMesh {
    std::vector<Vec3> positions;
    std::vector<Face> faces;
    std::vector<VertexInfo> info;
    std::vector<std::vector<int>> featureNbrs;  //!< per vertex: its neighbours along feature lines
};

//! The input surface as the remesher queries it.
class Surface {
public:
    //! The selected part of `surface` (which `tree` is of) with its border loops as curves, its
    //! target edge length `targetPerFace` per face or (empty) `target`. The arguments must
    //! outlive the Surface.
    Surface(const TriMesh& surface, const ClosestPointTree& tree, const std::vector<char>& selected,
            const std::vector<double>& targetPerFace, double target);
    //! Adds the feature lines (the edges of two selected faces among `featureEdges`) and the
    //! corners: `corners`, and where lines end, branch or meet a border.
    void addCurves(const std::vector<std::array<int, 2>>& featureEdges, const std::vector<int>& corners);

    const TriMesh& mesh;
    std::vector<int> component;  //!< per face: its connected component
    int componentCount = 0;
    std::vector<int> fanFirst, fan;        //!< CSR: the selected faces around each vertex
    std::vector<CurveEdge> curves;         //!< border edges, then feature edges
    std::vector<int> curveFirst, curveOf;  //!< CSR: the curve edges at each vertex
    std::vector<char> stop;                //!< per vertex: a corner (curves end, branch or meet there)

    //! The selected faces, each vertex a corner (stop), on a border, on a feature line or free.
    StartMesh startMesh() const;
    double target(int face) const { return perFace_.empty() ? uniform_ : perFace_[face]; }
    //! The target edge length at p on `face`: the face's, or shorter near a narrow strip.
    double targetAt(const Vec3& p, int face) const
    {
        const double own = target(face);
        return strips_ ? std::min(own, strips_->at(p)) : own;
    }
    //! Shorter edges near narrow strips (null: none); must outlive the Surface.
    void setStripSizing(const StripSizing* strips) { strips_ = strips; }
    //! The closest point to p on p's own sheet: a walk over the faces from `face`; the tree's
    //! answer if the walk does not settle and that lies within `radius` of where it got. False
    //! (refused) if the answer's face is turned away from `normal`.
    bool projectFree(const Vec3& p, int face, const Vec3& normal, double radius, Spot& out) const;
    //! The closest point to p on the curve through `edge`, looked for up to an arc length
    //! `radius` each way and never past a corner.
    void projectOnCurve(const Vec3& p, int edge, double radius, Spot& out) const;
    //! projectOnCurve from each curve edge of kind `border` at surface vertex `corner`.
    bool projectFromCorner(const Vec3& p, int corner, bool border, double radius, Spot& out) const;

private:
    bool walk(const Vec3& p, int face, ClosestPoint& out) const;

    const std::vector<char>& selected_;
    const ClosestPointTree& tree_;
    std::vector<Vec3> normals_;  //!< unit face normals
    std::vector<int> across_;    //!< per half-edge 3 f + k: the selected face across it, -1 if none
    const std::vector<double>& perFace_;
    double uniform_;
    const StripSizing* strips_ = nullptr;
};

}  // namespace fieldcvt::local_remesh_detail
