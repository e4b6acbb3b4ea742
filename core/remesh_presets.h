#pragma once
// Presets: named sets of RemeshParams for a user who wants speed or the best mesh rather than the
// default's balance. A preset only sets fields a front end's options can still override (the CLI's
// --preset comes first, every other option after it). The measurements behind each set:
// docs/tuning.md, "Presets".
#include "errors.h"
#include "remesh_params.h"

#include <string>

namespace fieldcvt {

enum class Preset {
    //! A short schedule for the time of edge-length remeshers (pmp, CGAL) with FCVT's regularity:
    //! the lattice start is already even and field-aligned, so 5 FCVT iterations (no CVT ones),
    //! a coarser field and lattice solve, a shorter valence stage without the sag repair and a
    //! coarser optimisation surface (2 faces a sample, simplified in parallel blocks) keep V6 and
    //! Q_avg above theirs at a fraction of the default's time.
    Fast,
    //! RemeshParams' own defaults.
    Default,
    //! The paper's long schedule (§5: 30 Lloyd steps, 65 CVT and 65 FCVT iterations), the field
    //! and the lattice solved with twice the sweeps, optimised on the input itself: for a user
    //! who wants the best mesh and has the time.
    Quality,
};

inline const char* presetName(Preset preset)
{
    switch (preset) {
    case Preset::Fast: return "fast";
    case Preset::Default: return "default";
    case Preset::Quality: return "quality";
    }
    return "default";
}

//! "fast", "default" or "quality"; anything else is an InvalidInputError naming the three.
inline Preset presetFromName(const std::string& name)
{
    for (Preset p : {Preset::Fast, Preset::Default, Preset::Quality})
        if (name == presetName(p)) return p;
    throw InvalidInputError("the preset must be fast, default or quality, got '" + name + "'");
}

//! Sets the fields of `params` that `preset` names (schedule, field and lattice sweeps, valence
//! stage, optimisation surface) on parameters that have RemeshParams' defaults there, as a front
//! end's do before its options are read; the others (vertex count, seed, features, ...) stay.
inline void applyPreset(RemeshParams& params, Preset preset)
{
    const RemeshParams defaults;
    switch (preset) {
    case Preset::Default: break;
    case Preset::Fast:
        params.cvtIterations = 0;
        params.fcvtIterations = params.largeRunFcvtIterations = 5;
        params.boundaryIterations = 3;
        params.fieldSmoothingIterations = 8;
        params.latticeIterations = 2;
        params.latticePasses = 2;
        params.optimisationFacesPerSample = 2;  // the least a sample (optimisationFaceTarget)
        params.simplifyBlockFaces = 16000;      // in parallel from 32 000 faces on
        params.valence.maxRounds = 10;
        params.valence.lookAheadDepth = 2;
        params.valence.relaxIterations = 3;
        params.valence.localSmoothing = 1;
        params.valence.sagRepairRounds = 0;
        break;
    case Preset::Quality:
        usePaperSchedule(params);
        params.largeRunFcvtIterations = params.fcvtIterations;
        params.fieldSmoothingIterations = 2 * defaults.fieldSmoothingIterations;
        params.latticeIterations = 2 * defaults.latticeIterations;
        params.optimisationFacesPerSample = 0;  // on the input, as the paper does
        break;
    }
}

}  // namespace fieldcvt
