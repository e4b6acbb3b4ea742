#pragma once
// The mesh the valence stage (§4.4) optimises: an EditableMesh whose vertices carry their
// closest point on the input surface, the surface normal there, their role and their valence
// (all undone with the edits); R's terms, ordered rings, face shape, and the moves that keep a
// vertex on the surface (or its feature line).
#include "closest_point.h"
#include "editable_mesh.h"
#include "triangle_shape.h"
#include "valence/surface.h"
#include "valence/tuning.h"
#include "valence_params.h"

#include <memory>
#include <vector>

namespace fieldcvt::valence {

//! What each vertex of the optimised mesh carries besides its position.
struct MeshVertex {
    ClosestPoint closest;  //!< its closest point on the input
    Vec3 normal;           //!< the input's (interpolated) normal there
    VertexRole role = VertexRole::Free;
    bool onBorder = false;  //!< on an edge of one face: target valence 4; never changes
    bool manifold = true;   //!< its faces form a single fan (else it is never touched)
    int valence = 0;        //!< neighbours in its ring
};

//! The ordered neighbours of a vertex, counter-clockwise: face i is (v, verts[i], verts[i+1])
//! (indices mod size for a closed fan). `ok` is false for a vertex whose faces do not form a
//! single fan (non-manifold): such vertices are never touched.
struct Ring {
    std::vector<int> verts;
    std::vector<int> faces;
    bool closed = true;
    bool ok = true;
};

inline bool isFeatureLike(VertexRole r) { return r == VertexRole::Feature || r == VertexRole::Corner; }
//! Vertices that neither the smoothing after an operation nor the relaxation moves: a border
//! vertex stays where the border's 1D CVT put it (see docs/tuning.md, "Border vertices stay").
inline bool isFixed(VertexRole r) { return r == VertexRole::Corner || r == VertexRole::Boundary; }

class ValenceMesh : public EditableMesh<MeshVertex> {
public:
    //! `mesh` and `roles` checked by the caller (indices, sizes, no repeated corner); Free
    //! vertices on the mesh's border are put on `surface.border` and become Boundary.
    ValenceMesh(const TriMesh& mesh, const std::vector<VertexRole>& roles, const ValenceSurface& surface, int borderWeight,
                const std::vector<int>& faceHints);

    const ValenceSurface& surface() const { return *surface_; }
    //! Distance bounds on the input, shared by the copies of the mesh.
    const SurfaceWalk& walk() const { return *walk_; }
    //! Mean edge length at the start: the unit of every length limit of the stage.
    double edgeLength() const { return edgeLength_; }

    // --- R = Σ w(v)·(d(v) − o(v))² ---------------------------------------------------------
    int target(int v) const { return data(v).onBorder ? 4 : 6; }
    int weight(int v) const { return data(v).onBorder ? borderWeight_ : 1; }
    //! v's term of R at valence `valence`.
    int cost(int v, int valence) const
    {
        const int d = valence - target(v);
        return weight(v) * d * d;
    }
    int valenceDelta(int v, int delta) const { return cost(v, data(v).valence + delta) - cost(v, data(v).valence); }
    long long irregularity() const;
    //! Recomputes the valence and manifold flag of the alive vertices of `verts` from their rings.
    void refreshValences(const std::vector<int>& verts);
    void ring(int v, Ring& r) const;

    // --- shape --------------------------------------------------------------------------------
    Vec3 surfaceNormal(const ClosestPoint& cp) const;
    Vec3 faceUnitNormal(int f) const;
    //! Face f's smallest angle (radians) and the agreement (cosine) of its normal with the mean
    //! of its corners' surface normals (-1 without one).
    void faceShape(int f, double& angle, double& dot) const;
    //! Smallest angle and smallest normal agreement over `faces`.
    void localShape(const std::vector<int>& faces, double& minAngle, double& minDot) const;
    //! The alive faces around the alive vertices of `verts`, sorted, without repeats.
    void facesAround(const std::vector<int>& verts, std::vector<int>& faces) const;

    // --- moves on the surface -----------------------------------------------------------------
    //! v to `p` with closest point `cp` (and the normal there).
    void place(int v, const Vec3& p, const ClosestPoint& cp);
    void place(int v, const ClosestPoint& cp) { place(v, cp.point, cp); }
    //! A new vertex at p (its closest point measured, p itself kept).
    int addSurfaceVertex(const Vec3& p, VertexRole role);
    //! Moves v towards `goal` as its role allows (tangentially, then on the surface / its line).
    void moveTowards(int v, const Vec3& goal);
    //! §4.4's local tangential smoothing: `steps` Gauss–Seidel sweeps of `verts` (index order)
    //! towards their one-ring centroids.
    void smoothLocally(const std::vector<int>& verts, int steps);

    //! Mean direction distance D (eq. 3) over the directed edges, the field at the first vertex.
    double meanFieldDistance() const;
    //! The alive vertices and faces, renumbered in order, with their roles.
    void compact(TriMesh& mesh, std::vector<VertexRole>& roles) const;

private:
    Vec3 oneRingCentroid(int v) const;
    //! Where Free vertex v, on the mesh's border, goes (the other vertices at `at`): the closest
    //! point of the input's `border`, unless that flattens one of its faces.
    Vec3 placeOnBorder(int v, const std::vector<Vec3>& at, const std::vector<Segment>& border) const;

    const ValenceSurface* surface_;
    std::shared_ptr<const SurfaceWalk> walk_;
    std::shared_ptr<const std::vector<Vec3>> inputNormals_;  //!< area-weighted vertex normals of the input
    int borderWeight_ = 1;
    double edgeLength_ = 1;
};

}  // namespace fieldcvt::valence
