#pragma once
// The parameters of the thin-part stage (thin_parts.h), which remesh()'s parameters carry.

namespace fieldcvt {

struct ThinPartParams {
    //! The output's edges are at most this times the local thickness where the surface is
    //! thinner than the uniform edge length divided by it (docs/measurements.md, "thin parts").
    double edgePerThickness = 1.0;
    //! Edges on a strip of surface between two borders (a peninsula of a ragged border, the land
    //! between two holes) at most this times its width: two rows of triangles across, where one
    //! row of cells would make a chain of cells and no triangle (docs/tuning.md, "edgePerStripWidth").
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

}  // namespace fieldcvt
