#pragma once
// The figures of a mesh that metrics.h computes (Table 2 of the paper, topology), which
// remesh()'s result and the front ends' reports carry.
#include <limits>

namespace fieldcvt {

//! Topology of a triangle mesh, from its edge structure.
struct TopologySummary {
    int vertices = 0;  //!< referenced vertices
    int faces = 0;
    int edges = 0;
    int components = 0;  //!< connected components (through shared edges)
    int boundaryLoops = 0;
    int nonManifoldEdges = 0;     //!< edges with more than two faces
    int nonManifoldVertices = 0;  //!< vertices whose faces form more than one fan
    bool orientable = true;       //!< faces consistently oriented across every manifold edge
    int genus = 0;                //!< sum over components of (2 - chi - b) / 2; meaningful if manifold
    bool manifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
};

struct QualityMetrics {
    int vertices = 0;        //!< |X|
    int faces = 0;           //!< |t|
    double qMin = 0;         //!< min over triangles of Q = 2 sqrt(3) |t| / (s h)
    double qAvg = 0;         //!< mean Q
    double thetaMin = 0;     //!< smallest angle, degrees
    double thetaMinAvg = 0;  //!< mean over triangles of the smallest angle, degrees
    double thetaMax = 0;     //!< largest angle, degrees
    double pctLt30 = 0;      //!< % of triangles whose smallest angle is < 30 degrees
    double pctGt90 = 0;      //!< % of triangles whose largest angle is > 90 degrees
    double v6Pct = 0;        //!< % of interior vertices of valence 6
    //! Distances to a reference surface, as fractions of the reference's bounding-box diagonal;
    //! NaN when no reference was given.
    double dRms = std::numeric_limits<double>::quiet_NaN();
    double dH = std::numeric_limits<double>::quiet_NaN();
    //! Hausdorff distance between the open boundaries of the mesh and of the reference, as a
    //! fraction of the reference's diagonal; NaN without a reference or without boundaries.
    double dBoundary = std::numeric_limits<double>::quiet_NaN();
    //! % of boundary vertices of valence 4 (the boundary's regular valence); NaN if closed.
    double boundaryV4Pct = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace fieldcvt
