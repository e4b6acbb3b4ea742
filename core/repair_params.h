#pragma once
// The parameters and the report of the input repair (repair.h), which remesh()'s parameters
// and result carry.
#include <string>
#include <vector>

namespace fieldcvt {

struct RepairParams {
    //! Welding distance as a fraction of the mean edge length of the input.
    double weldTolerance = 1e-3;
    //! false: no vertex is merged with another (exact duplicates, welds, T-junctions): for a part
    //! cut out of a mesh (region.h), whose vertices must stay those the rest of the mesh shares,
    //! and for a surface repaired that way already, whose split copies a merge would glue back.
    bool mergeVertices = true;
    //! Output vertex count the surface will be remeshed with; 0 = no component is dropped.
    int vertexBudget = 0;
    //! A component is dropped when it would get fewer samples than this (vertexBudget × its
    //! share of the area): fewer samples than a tetrahedron's few make no surface of it.
    double minComponentSamples = 8;
    //! ... unless it holds at least this fraction of the area (kept, with a warning): a part
    //! (part_coverage.h counts components from 0.5 % of the area), which must come back.
    double keepAreaFraction = 0.005;
    //! ... or it lies farther than this many edge lengths (of vertexBudget vertices over the
    //! whole area) from every component kept for its size: a part on its own, whose loss would
    //! show as a gap in the output (d_H), not a crumb beside the rest. Kept then if it also
    //! gets at least minFarComponentSamples expected samples (half a triangle's area: less
    //! makes no triangle of the output's size), largest first while the samples they are
    //! short of minFarComponentFloor come to at most farComponentBudget × vertexBudget.
    double farComponentEdges = 2;
    double minFarComponentSamples = 0.25;
    double minFarComponentFloor = 3;  //!< the samples each kept far component gets at least (sampling.h)
    double farComponentBudget = 0.02;
};

struct RepairReport {
    int removedUnreferencedVertices = 0;
    int mergedDuplicateVertices = 0;  //!< same coordinates as another vertex
    int weldedVertices = 0;           //!< border vertices merged within the tolerance
    int tJunctions = 0;               //!< border vertices inserted into a border edge
    double weldDistance = 0;          //!< the tolerance in input units
    int removedDegenerateFaces = 0;   //!< repeated corner (also after welding) or zero area
    int removedDuplicateFaces = 0;    //!< same corners, same orientation as an earlier face
    int removedOppositeFaces = 0;     //!< same corners, opposite orientation
    int removedFlapFaces = 0;         //!< doubled faces hanging from one edge: their last copy too
    int nonManifoldEdges = 0;         //!< edges with more than two faces, split
    int nonOrientableComponents = 0;  //!< components cut so that each piece is orientable
    int seamEdges = 0;                //!< edges cut for that
    int splitVertices = 0;            //!< vertices split into one vertex per fan
    int addedVertexCopies = 0;        //!< copies added by those splits
    int droppedComponents = 0;        //!< too small for the vertex budget
    double droppedArea = 0;           //!< their area, input units
    double droppedAreaFraction = 0;   //!< their share of the total area
    int keptSmallComponents = 0;      //!< too small for the budget but over keepAreaFraction
    int keptFarComponents = 0;        //!< too small for the budget but far from the rest
    bool skipped = false;             //!< bad indices or coordinates: left to the strict check
    std::vector<std::string> notes;   //!< one line per step that changed the surface (warnings)
    //! One line per step that changed nothing a user sees (unreferenced vertices removed, exact
    //! duplicates merged): information, not warnings.
    std::vector<std::string> information;
    //! Per input vertex: its index in the repaired mesh, -1 if removed.
    std::vector<int> vertexMap;
    //! Per vertex of the repaired mesh: the input vertex it is or is a copy of (a split).
    std::vector<int> vertexSource;
};

}  // namespace fieldcvt
