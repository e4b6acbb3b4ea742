#pragma once
// Thin parts (issue 32, item 2): where the surface is thinner than the output's edge length (a
// plate, a handle, the wall around a narrow hole), the restricted Voronoi cells of samples on one
// side reach the other side and the RDT tears or glues the shell. This stage measures the
// surface's local thickness with medial balls and raises the vertex density there, by as much as
// the thickness needs, so that the kept shell comes back closed with its genus.
//
// Thickness. At a surface point p with normal n, the medial ball on each side is the largest
// ball touching the surface at p and empty of it; the shrinking-ball iteration finds it with
// closest-point queries only (Ma, Bae and Choi, "3D medial axis point approximation using nearest
// neighbors and the normal field", 2012). A ball that touches the surface again roughly opposite p
// (its "object angle" over `minObjectAngleDegrees`) spans a thin part: a plate's two faces, or a
// hole's two walls; a ball stopped by a concave crease (angle about 90°) does not. The thickness
// is the ball's diameter.
#include "closest_point.h"
#include "mesh.h"

#include <vector>

namespace fieldcvt {

struct ThinPartParams {
    //! The output's edges are at most this times the local thickness where the surface is
    //! thinner than the uniform edge length divided by it. Chosen by measurement on the CAD parts
    //! of ../shared/realworld (docs/measurements.md, "thin parts").
    double edgePerThickness = 1.0;
    //! Edges on a strip of surface between two borders (a peninsula of a ragged border, the land
    //! between two holes) at most this times its width: two rows of triangles across, where one
    //! row of cells would make a chain of cells and no triangle (1 left lato180.ply in 13 pieces
    //! at 5 589 vertices, 0.5 in 2; docs/measurements.md, "Parts").
    double edgePerStripWidth = 0.5;
    //! A medial ball counts as spanning a thin part when the two points where it touches the
    //! surface are at least this angle apart, seen from its centre (180° on a flat plate, 90° in
    //! a right-angled concave crease).
    double minObjectAngleDegrees = 150;
    //! Grading: the wanted edge length grows by at most this much per unit of distance away from
    //! a thin part, so that the cells' size changes smoothly.
    double gradation = 0.5;
    //! The vertex count may grow to at most this times the one asked for; where the thin parts
    //! would need more, the finest edges are capped (the topology may then not be recovered).
    //! Under 2 because cells in several pieces (thin parts) each make an output vertex.
    double maxVertexFactor = 1.9;
    //! The finest edges are this many times shorter than the uniform ones, at most (a sliver of
    //! a thin part, 1e-5 edge lengths across, does not ask for a million times the density).
    double maxEdgeRatio = 8;
};

struct ThinPartDensity {
    //! Per face of the surface: the vertex density μ (output vertices per unit area, relative to
    //! the uniform one: 1 away from thin parts). Empty when nothing is thin.
    std::vector<double> mu;
    //! ∫ μ dA / area: the vertex count the density needs, relative to the uniform one (1 when
    //! nothing is thin, at most ThinPartParams::maxVertexFactor).
    double vertexFactor = 1;
    int thinFaces = 0;    //!< faces measured thinner than the edge length allows
    double thinnest = 0;  //!< the smallest thickness measured (0 when none is thin)
    bool capped = false;  //!< maxVertexFactor limited the density
};

//! The local thickness at p (normal `normal`, unit; `face`: p's face, a hint) on the side the
//! normal points to (`side` = +1) or the opposite one (-1): the diameter of the ball tangent at p
//! that touches the surface again opposite p (ThinPartParams::minObjectAngleDegrees), shrunk
//! while its contacts are opposite; +infinity when there is none under `largest` across.
double localThickness(const ClosestPointTree& tree, const Vec3& p, const Vec3& normal, int face, int side, double largest,
                      double minObjectAngleDegrees);

//! Where to look for thin parts: faces whose centroid lies within `radius` of one of `points`
//! (e.g. where an RDT tore); no points = everywhere.
struct ThinPartFocus {
    std::vector<Vec3> points;
    double radius = 0;
};

//! The density that thin parts need on `surface` (at the working scale, where the uniform edge
//! length is `edgeLength`). `tree` is the surface's.
ThinPartDensity thinPartDensity(const TriMesh& surface, const ClosestPointTree& tree, double edgeLength,
                                const ThinPartParams& params = {}, const ThinPartFocus& focus = {});

}  // namespace fieldcvt
