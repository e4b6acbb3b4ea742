#pragma once
// (Not "features.h": that name is glibc's <features.h>, which this include path would shadow.)
// Sharp features (§5, "Sharp feature handling"): feature lines from the dihedral angle or from
// the user, their corners, and the second stage of the two-stage strategy: after a free
// optimisation, the samples whose restricted cell meets a feature line are snapped to it and
// move only along it (a 1D CVT of the feature curves); samples at corners stay fixed.
#include "boundary.h"
#include "energy.h"
#include "mesh.h"

#include <array>
#include <vector>

namespace fieldcvt {

struct FeatureLines {
    std::vector<std::array<int, 2>> edges;  //!< feature edges (surface vertex pairs, smaller first), sorted
    std::vector<Segment> segments;          //!< the same edges as segments
    //! Surface vertices where the lines end (1 feature edge), branch (≥ 3), meet the open
    //! border or turn by more than 45°, and where the open border turns by more than 45°, sorted.
    std::vector<int> corners;
    bool empty() const { return segments.empty() && corners.empty(); }
};

//! Feature lines of `surface`: interior edges whose dihedral angle (between the two face
//! normals) is at least `angleDegrees` (0 = none), plus `userEdges` (vertex pairs of `surface`
//! that must be edges of it; others are ignored and counted in `ignoredUserEdges`), and the
//! corners of the lines and of the open border. A corner closer than `cornerSpacing` to a more
//! important one (line ends and branches first, then sharper turns) is left out.
FeatureLines detectFeatures(const TriMesh& surface, double angleDegrees, const std::vector<std::array<int, 2>>& userEdges = {},
                            int* ignoredUserEdges = nullptr, double cornerSpacing = 0);

//! Where each sample ended up after relaxConstrainedSamples (what it may do afterwards).
enum class SampleConstraint : char { Free, Border, Feature, Corner };

//! The second stage (§5): `iterations` Lloyd-type steps in which a sample whose cell meets the
//! open border moves to the centroid of the border inside its cell (projected on the border),
//! a sample whose cell meets a feature line moves to the centroid of the feature curve inside its
//! cell (projected on the line), the sample nearest to each corner sits on that corner, and,
//! where there are feature lines or `iterationsFollow` is false, the others move to their cell's
//! centroid (else they stay for the iterations that follow to move: only the border faces' part
//! of the RVD is computed). Returns what each sample is; the caller freezes the constrained ones
//! for the remaining (FCVT) iterations.
std::vector<SampleConstraint> relaxConstrainedSamples(EnergyFunction& energy, std::vector<Vec3>& seeds, const TriMesh& surface,
                                                      const std::vector<Segment>& border, const FeatureLines& features,
                                                      int iterations, bool iterationsFollow = true);

//! One connected piece of the feature lines inside one sample's cell (its 1D restricted
//! Voronoi cell can have several: two lines that pass close to each other).
struct CurvePiece {
    int seed = -1;
    double length = 0;
    Vec3 moment = Vec3::Zero();  //!< ∫ x ds over the piece
    std::vector<int> segments;   //!< the feature segments it runs on (sorted)
};

//! The pieces of the feature lines nearest to each seed (measured on points spaced at most
//! `spacing` apart), sorted by seed, then by decreasing length.
std::vector<CurvePiece> restrictCurvesToCells(const std::vector<Vec3>& seeds, const FeatureLines& lines, double spacing);

//! Largest distance from the feature lines (sampled at `spacing`) to the edges of `mesh` whose
//! dihedral angle is at least `angleDegrees`, or to any edge of `mesh` if angleDegrees <= 0.
//! The figure behind "every input feature edge lies on an output edge chain".
double featureDeviation(const FeatureLines& features, const TriMesh& mesh, double angleDegrees, double spacing);

}  // namespace fieldcvt
