#pragma once
// The sag guard of the valence stage: how far a face of the optimised mesh lies from the input
// surface (its sag: the largest distance of its centroid and edge midpoints to the input, large
// where it cuts across a crease or a thin part), whether a face sags more than a limit, and the
// limits themselves (an operation's, the relaxation's, the angle repair's). One cache per face
// serves every question: per sag point, an upper bound of its distance (a walk's, or the exact
// one) at the corner positions it was measured for; after the corners move by m0..m2, the bound
// plus the point's move still bounds the distance (it is 1-Lipschitz), so only the points that
// may exceed the limit are measured again, by a walk first and by the tree where the walk's
// bound still exceeds it. Every answer is the one the exact sags would give.
#include "valence/valence_mesh.h"

#include <array>
#include <vector>

namespace fieldcvt::valence {

class SagGuard {
public:
    //! The mesh must outlive the guard; the guard follows its edits (faces are told apart by
    //! index, corners and corner positions).
    explicit SagGuard(const ValenceMesh& mesh) : mesh_(mesh) {}

    //! Face f's sag (exact), remembered for its corner positions.
    double sag(int f);
    //! At least sag(f), from walks over the input (usually equal to it); no cache.
    double bound(int f) const;
    //! Whether sag(f) > limit. Safe in parallel for distinct faces once sized (relaxationLimits).
    bool exceeds(int f, double limit);
    //! Whether one of `faces` sags more than `limit`.
    bool exceedsAny(const std::vector<int>& faces, double limit);

    //! The largest sag an operation may leave on the faces around it, from `faces` before it:
    //! the largest max(min(growth × sag, sag + step), floor) (kOperationSagGrowth, kOperationSagStep).
    double operationLimit(const std::vector<int>& faces);
    //! The angle repair's limit for a vertex with `faces`: max(kRelaxSagGrowth × their largest
    //! sag, floor).
    double repairLimit(const std::vector<int>& faces);
    //! Per face (alive ones; the connectivity fixed from now on), the relaxation's limit from the
    //! sags at its start: max(kRelaxSagGrowth × the face's sag, max(floor, kRelaxSagShareOfLargest ×
    //! the largest sag of any face)). Also sizes the cache for every face.
    std::vector<double> relaxationLimits();

private:
    static constexpr unsigned char kAllExact = 0xF;
    struct Entry {
        Face face = {-1, -1, -1};      //!< the corners the entry is for
        std::array<Vec3, 3> corners;   //!< their positions when the bounds were measured
        std::array<double, 4> bound;   //!< per sag point (sagPoints' order), at least its distance
        std::array<int, 4> walkStart;  //!< per sag point, the face its last walk ended on (-1: none)
        unsigned char exact = 0;       //!< bit k: bound[k] is point k's exact distance
    };

    //! The points whose distance to the input makes face f's sag (centroid, midpoints of edges
    //! 01, 12, 20), and for each the face its query starts from.
    void sagPoints(int f, Vec3 (&points)[4], int (&starts)[4]) const;
    double exactDistance(const Vec3& point, int start) const;
    //! f's entry; empty (no bound yet) unless it is for f's corners.
    Entry& entry(int f);
    //! Whether the entry's corner positions are f's corners' positions now.
    bool unmoved(const Entry& e) const;
    //! An upper bound of sag(f): the entry's if its corners have not moved, else walks.
    double knownBound(int f);
    double floor() const;

    const ValenceMesh& mesh_;
    std::vector<Entry> cache_;  //!< per face index
};

}  // namespace fieldcvt::valence
