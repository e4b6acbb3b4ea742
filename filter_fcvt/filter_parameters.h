#pragma once
// The filters' parameters, shared by their declaration (filter_parameters.cpp) and their reading
// (fcvt_filters.cpp): the defaults that depend on the layer, the .mlx enums (index = the value
// stored in scripts, frozen), and readers for parameters an older script may lack.
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "filter_types.h"
#include "field.h"
#include "remesh.h"
#include "remesh_presets.h"

namespace fcvt_plugin {

// Upper end of the default vertexCount: the paper's typical output size (Table 1), and a run
// of a few seconds on two cores; inputs with fewer vertices default to their own count.
constexpr int kDefaultMaxVertices = 5000;

inline int defaultVertexCount(const MeshModel* m)
{
    const int vn = m != nullptr ? m->cm.vn : kDefaultMaxVertices;
    return std::max(fieldcvt::kMinVertexCount, std::min(vn, kDefaultMaxVertices));
}

// Bounding-box diagonal of the layer (1 without a mesh): the range of targetLength.
inline float bboxDiagonal(const MeshModel* m)
{
    const float d = m != nullptr && !m->cm.bbox.IsNull() ? float(m->cm.bbox.Diag()) : 0.0f;
    return std::isfinite(d) && d > 0 ? d : 1.0f;
}

// The sizeMode enum (index = value in .mlx scripts, frozen).
enum SizeMode { kSizeByVertexCount = 0, kSizeByTargetLength = 1 };
inline const QStringList kSizeModeLabels = {"vertex count", "target edge length"};

// The adaptive enum, the density source (index = value in .mlx scripts, frozen). Scripts written
// before it was an enum carry adaptive as a bool: false = uniform, true = vertex quality.
enum DensityChoice { kDensityUniform = 0, kDensityCurvature = 1, kDensityVertexQuality = 2 };
inline const QStringList kDensityLabels = {"uniform", "curvature", "vertex quality"};

// A parameter that a script may lack (added after the first release): its value, or `fallback`.
inline bool boolParam(const ParamValues& par, const char* key, bool fallback)
{
    return par.hasParameter(key) ? par.getBool(key) : fallback;
}

// An enum a script may lack: its index (any integer: MeshLab does not check the range), or
// `fallback`.
inline int enumParam(const ParamValues& par, const char* key, int fallback)
{
    return par.hasParameter(key) ? par.getEnum(key) : fallback;
}

inline double floatParam(const ParamValues& par, const char* key, double fallback)
{
    return par.hasParameter(key) ? double(par.getFloat(key)) : fallback;
}

// The density source: the adaptive enum, or the bool of scripts from before it was one
// (true = vertex quality); uniform when the script has neither.
inline int densityChoice(const ParamValues& par)
{
    if (!par.hasParameter(kAdaptive)) return kDensityUniform;
    if (par.isBool(kAdaptive)) return par.getBool(kAdaptive) ? kDensityVertexQuality : kDensityUniform;
    return par.getEnum(kAdaptive);
}

// The preset enum (index = value in .mlx scripts, frozen): fieldcvt::Preset's order, labelled
// with presetName (the CLI's --preset values).
constexpr fieldcvt::Preset kPresets[] = {fieldcvt::Preset::Fast, fieldcvt::Preset::Default, fieldcvt::Preset::Quality};
constexpr int kPresetCount = int(std::size(kPresets));
constexpr int kDefaultPresetIndex = 1;
static_assert(kPresets[kDefaultPresetIndex] == fieldcvt::Preset::Default);
inline QStringList presetLabels()
{
    QStringList labels;
    for (fieldcvt::Preset p : kPresets) labels << fieldcvt::presetName(p);
    return labels;
}

// The fieldSource enum: index in the RichEnum (the value stored in .mlx scripts, frozen) ->
// core source. "Compute 6-RoSy Field" offers the first kComputedFieldSources entries.
struct FieldSourceChoice {
    fieldcvt::FieldSource source;
    const char* label;
};
constexpr FieldSourceChoice kFieldSources[] = {
    {fieldcvt::FieldSource::Extrinsic, "extrinsic 6-RoSy"},
    {fieldcvt::FieldSource::CurvatureMax, "max curvature"},
    {fieldcvt::FieldSource::CurvatureMin, "min curvature"},
    {fieldcvt::FieldSource::User, "per-vertex attribute rosy"},
};
constexpr int kAllFieldSources = int(std::size(kFieldSources));
constexpr int kComputedFieldSources = 3;

inline QStringList fieldSourceLabels(int count)
{
    QStringList labels;
    for (int i = 0; i < count; ++i) labels << kFieldSources[i].label;
    return labels;
}

inline int fieldSourceIndex(fieldcvt::FieldSource source)
{
    for (int i = 0; i < kAllFieldSources; ++i)
        if (kFieldSources[i].source == source) return i;
    return 0;
}

//! The declarations of one filter, in order.
struct ParamList {
    std::vector<ParamDef> defs;
    void addParam(ParamDef p) { defs.push_back(std::move(p)); }
};

//! Declares filter `a`'s parameters (defaults from layer `m` of document `md`, either may be null).
void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par);

}  // namespace fcvt_plugin
