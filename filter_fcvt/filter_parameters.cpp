#include "filter_parameters.h"

#include "log_text.h"

namespace fcvt_plugin {

namespace {

// The parameter declarations below read like both MeshLabs' own (par.addParam(RichInt(...)));
// these build the neutral ParamDef the glue turns into its MeshLab's Rich* parameters.

ParamDef makeParam(ParamDef::Type type, const char* name, double value, const QString& label, const QString& tooltip)
{
    ParamDef p;
    p.type = type;
    p.name = name;
    p.value = value;
    p.label = label;
    p.tooltip = tooltip;
    return p;
}
ParamDef RichInt(const char* name, int value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Int, name, value, label, tooltip);
}
ParamDef RichFloat(const char* name, float value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Float, name, double(value), label, tooltip);
}
ParamDef RichBool(const char* name, bool value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Bool, name, value ? 1 : 0, label, tooltip);
}
ParamDef RichEnum(const char* name, int value, const QStringList& labels, const QString& label, const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::Enum, name, value, label, tooltip);
    p.enumLabels = labels;
    return p;
}
ParamDef RichAbsPerc(const char* name, float value, float min, float max, const QString& label, const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::AbsPerc, name, double(value), label, tooltip);
    p.min = double(min);
    p.max = double(max);
    return p;
}
//! Marks a parameter few users change (ParamDef::advanced).
ParamDef advanced(ParamDef p)
{
    p.advanced = true;
    return p;
}
ParamDef RichMesh(const char* name, const MeshModel*, const MeshDocument*, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Mesh, name, 0, label, tooltip);
}

}  // namespace

void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par)
{
    const int vertexCountDefault = defaultVertexCount(m);
    const float diagonal = bboxDiagonal(m);
    switch (a) {
    case kRemesh: {
        // Core defaults are the single source of truth for everything but vertexCount.
        const fieldcvt::RemeshParams defaults;
        // The dialog's order: what most runs set first, the optimiser's knobs after. Scripts
        // match parameters by name (RichParameterList::getParameterByName), so the order is free;
        // a new parameter still goes at the end, where meshlabserver adds a missing one.
        par.addParam(RichInt(kVertexCount, vertexCountDefault, parameterLabel(kVertexCount),
                             "Number of output vertices (Voronoi samples), at least 4. Default: "
                             "the input's vertex count, capped at 5000."));
        par.addParam(RichEnum(kSizeMode, kSizeByVertexCount, kSizeModeLabels, parameterLabel(kSizeMode),
                              "How the output size is given: by the number of vertices (Target "
                              "vertices) or by the edge length (Target edge length), converted to "
                              "a vertex count through the surface area."));
        par.addParam(RichAbsPerc(kTargetLength, 0.01f * diagonal, 0.0f, diagonal, parameterLabel(kTargetLength),
                                 "Wanted edge length in world units (used when Size by is 'target "
                                 "edge length'); the vertex count is about 2 * area / (sqrt(3) * "
                                 "length^2). Default: 1% of the bounding-box diagonal."));
        par.addParam(RichEnum(kAdaptive, kDensityUniform, kDensityLabels, parameterLabel(kAdaptive),
                              "Where the vertices go, the vertex count unchanged: uniform; more where "
                              "the surface bends (curvature, graded by Curvature gradation); or more "
                              "where the input's per-vertex quality is higher (every value must be "
                              "finite and above 0)."));
        par.addParam(advanced(RichFloat(kGradation, float(defaults.gradation), parameterLabel(kGradation),
                                        "With Vertex density 'curvature': how strongly curvature raises the "
                                        "density (0 or more; 0 = uniform, 1 = edges up to about 3 times "
                                        "shorter where the surface bends most).")));
        par.addParam(RichFloat(kFeatureAngle, float(defaults.featureAngleDegrees), parameterLabel(kFeatureAngle),
                               "Input edges whose faces meet at a dihedral angle of at least this "
                               "many degrees are sharp features that the output follows; 0 = no "
                               "sharp features (0..180)."));
        par.addParam(RichBool(kValenceOptimization, defaults.valenceOptimization, parameterLabel(kValenceOptimization),
                              "After the extraction, edge flips, collapses and splits that bring "
                              "vertices to valence 6 (4 on boundaries), then a relaxation that "
                              "realigns the edges (paper section 4.4)."));
        par.addParam(advanced(RichBool(kColorIrregular, false, parameterLabel(kColorIrregular),
                                       "Colour the output's vertices by valence: blue below 6 (4 on a "
                                       "boundary), pink above, white at it. Replaces the colour carried "
                                       "over from the input.")));
        par.addParam(advanced(RichFloat(kLambda, float(defaults.lambda), parameterLabel(kLambda),
                                        "Weight of the field-alignment energy; 0 gives a pure isotropic "
                                        "CVT.")));
        par.addParam(advanced(RichEnum(kFieldSource, fieldSourceIndex(defaults.fieldSource), fieldSourceLabels(kAllFieldSources),
                                       parameterLabel(kFieldSource),
                                       "The 6-RoSy field the edges are aligned to: the extrinsically smooth "
                                       "field, the max or min principal-curvature direction, or the "
                                       "per-vertex Point3 attribute 'rosy' of the input layer.")));
        par.addParam(advanced(RichInt(kSeed, int(defaults.seed), parameterLabel(kSeed),
                                      "Seed of the initial sampling (0 or more); the same seed gives the same "
                                      "output.")));
        par.addParam(advanced(RichInt(kCvtIterations, defaults.cvtIterations, parameterLabel(kCvtIterations),
                                      "L-BFGS iterations on the CVT energy (the paper uses 130).")));
        par.addParam(advanced(RichInt(kFcvtIterations, defaults.fcvtIterations, parameterLabel(kFcvtIterations),
                                      QString("L-BFGS iterations on CVT + lambda * field energy, run after the CVT "
                                              "iterations. With the default, runs of %1 vertices or more from "
                                              "the lattice start do %2 (as good there); any other value is "
                                              "used at every size.")
                                          .arg(defaults.largeRunSamples)
                                          .arg(defaults.largeRunFcvtIterations))));
        par.addParam(advanced(RichBool(kFeatureSelection, false, parameterLabel(kFeatureSelection),
                                       "Also treat the border of the input's face selection (edges between a "
                                       "selected and an unselected face) as feature lines.")));
        // Added after issue 15's reordering (issue 17): at the end, like every new parameter.
        par.addParam(RichBool(kRepair, defaults.repair, parameterLabel(kRepair),
                              "Before remeshing, weld coincident and nearly coincident border "
                              "vertices (cracks, seams, T-junctions), remove duplicate and opposite "
                              "faces, split non-manifold edges and vertices, cut non-orientable "
                              "pieces along a seam, and drop components too small for the vertex "
                              "count; each step is counted in the log. Off: the strict check only, "
                              "which refuses non-manifold edges and non-orientable pieces."));
        // Issue 34, at the end like every new parameter.
        par.addParam(RichBool(kSelectedOnly, false, parameterLabel(kSelectedOnly),
                              "Remesh only the selected faces: the rest of the mesh is kept exactly "
                              "(coordinates and attributes), the selection's border vertices stay "
                              "where they are and the new faces meet them edge to edge. The target "
                              "vertices or edge length apply to the selected area; the new faces "
                              "are selected on the new layer."));
        // At the end like every new parameter: the core's exactCount (the CLI's --exact-count).
        par.addParam(advanced(RichBool(kExactCount, defaults.exactCount, parameterLabel(kExactCount),
                                       "By default the vertex count yields to the topology: where the "
                                       "surface is thinner than the edge length the density is raised, "
                                       "and a shell whose topology the triangulation still loses is "
                                       "remeshed by local operations on the input, so every shell, hole "
                                       "and handle is kept; the log says how many vertices were added "
                                       "and why. Checked: the vertex count asked for is kept and the "
                                       "topology may be lost (the log warns).")));
        // The core's presets (the CLI's --preset). A dialog always has a value, so CVT and FCVT
        // iterations at their defaults mean "as the preset says" (applyRemesh).
        par.addParam(advanced(RichEnum(kPreset, kDefaultPresetIndex, presetLabels(), parameterLabel(kPreset),
                                       QString("The optimiser's schedule (the CLI's --preset): fast, a third to "
                                               "half the default's time, the mesh as regular; quality, the paper's "
                                               "long schedule. CVT or FCVT iterations other than %1 / %2 "
                                               "override it.")
                                           .arg(defaults.cvtIterations)
                                           .arg(defaults.fcvtIterations))));
        break;
    }
    case kField: {
        const fieldcvt::FieldParams defaults;
        par.addParam(RichEnum(kFieldSource, fieldSourceIndex(defaults.source), fieldSourceLabels(kComputedFieldSources),
                              parameterLabel(kFieldSource),
                              "The extrinsically smooth 6-RoSy field (aligned to boundaries and "
                              "sharp edges), or the max or min principal-curvature direction."));
        par.addParam(RichInt(kSeed, int(defaults.seed), parameterLabel(kSeed),
                             "Seed of the random initial directions of the smooth field (0 or more); "
                             "the same seed gives the same field."));
        par.addParam(RichInt(kMaxCrosses, kDefaultMaxCrosses, parameterLabel(kMaxCrosses),
                             "The drawing layer shows the field as a cross at every vertex, or at "
                             "one vertex per cell of a grid when the mesh has more vertices than "
                             "this (at least 1)."));
        break;
    }
    case kQuality: {
        // The default reference is the measured layer itself, which means "no distances".
        const QString description = parameterLabel(kReferenceLayer);
        const char* tooltip =
            "The layer d_RMS and d_H are measured against (e.g. the input of the "
            "remeshing). The current layer itself: no distances.";
        if (md != nullptr && m != nullptr)
            par.addParam(RichMesh(kReferenceLayer, m, md, description, tooltip));
        else  // no document: a parameter without a mesh (only for completeness of the overload)
            par.addParam(RichMesh(kReferenceLayer, static_cast<MeshModel*>(nullptr), nullptr, description, tooltip));
        par.addParam(RichBool(kColorIrregular, true, parameterLabel(kColorIrregular),
                              "Colour the vertices by valence: blue below 6 (4 on a boundary), "
                              "pink above, white at it."));
        break;
    }
    default: break;
    }
}

}  // namespace fcvt_plugin
