#pragma once
// Thin parts: where the surface is thinner than the output's edge length (a
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
#include "thin_part_params.h"

#include <vector>

namespace fieldcvt {

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
