#pragma once
// What the MeshLab-neutral part of the plugin (fcvt_filters.h) and the glue of each MeshLab share:
// the filters' ids and kinds, the parameter names (frozen: the .mlx API), a parameter's neutral
// definition, the interfaces through which the glue hands over its parameter values and its log,
// and the failure a filter reports.
#include <QString>
#include <QStringList>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshlab_types.h"

namespace fcvt_plugin {

//! The filters, in the order the plugin lists them (the glue's action ids).
enum FilterId { kRemesh = 0, kField = 1, kQuality = 2 };
constexpr FilterId kFilterIds[] = {kRemesh, kField, kQuality};

//! What each MeshLab's FilterClass needs (the glue maps it to its own enum).
enum class FilterKind { Remeshing, Normal, MeasureAndVertexColouring };

// The parameter names are frozen API: they are the keys of .mlx scripts.
constexpr const char* kVertexCount = "vertexCount";
constexpr const char* kLambda = "lambda";
constexpr const char* kCvtIterations = "cvtIterations";
constexpr const char* kFcvtIterations = "fcvtIterations";
constexpr const char* kFieldSource = "fieldSource";
constexpr const char* kSeed = "seed";
constexpr const char* kSizeMode = "sizeMode";
constexpr const char* kTargetLength = "targetLength";
constexpr const char* kValenceOptimization = "valenceOptimization";
constexpr const char* kFeatureAngle = "featureAngle";
constexpr const char* kFeatureSelection = "featureSelection";
constexpr const char* kAdaptive = "adaptive";
//! Remeshing (default off) and quality report (default on): colour vertices by valence.
constexpr const char* kColorIrregular = "colorIrregular";
//! Remeshing: the density source (enum: uniform / curvature / vertex quality; older scripts
//! carry it as a bool, true = vertex quality) and the curvature gradation.
constexpr const char* kGradation = "gradation";
//! Field: at most this many crosses in the drawing layer.
constexpr const char* kMaxCrosses = "maxCrosses";
constexpr int kDefaultMaxCrosses = 2000;
//! Remeshing: repair the input first (repair.h); off = the strict check only.
constexpr const char* kRepair = "repair";
//! Remeshing: keep the vertex count asked for where the topology needs more (RemeshParams::
//! exactCount, the CLI's --exact-count); default off: the topology is kept.
constexpr const char* kExactCount = "exactCount";
//! Remeshing: the core's preset (remesh_presets.h, the CLI's --preset), an enum: fast / default /
//! quality; "CVT iterations" and "FCVT iterations" at their defaults leave the preset's.
constexpr const char* kPreset = "preset";
//! Remeshing: remesh only the selected faces (region.h), the rest kept; default off.
constexpr const char* kSelectedOnly = "selectedOnly";
//! Quality report: the layer d_RMS / d_H are measured against (itself = no distances).
constexpr const char* kReferenceLayer = "referenceLayer";
//! Name of the per-vertex Point3m attribute that holds a 6-RoSy field (representative d).
constexpr const char* kRosyAttribute = "rosy";
//! Label of the layer "Compute 6-RoSy Field" adds (MeshLab appends "(1)", ... if taken).
constexpr const char* kFieldLayerLabel = "6-RoSy field";

//! One parameter of a filter, as both MeshLabs declare it (RichInt, RichFloat, ...).
struct ParamDef {
    enum Type { Int, Float, Bool, Enum, AbsPerc, Mesh };
    Type type = Int;
    const char* name = "";    //!< frozen: the key in .mlx scripts
    double value = 0;         //!< default: the int, float, bool (0/1), enum index or absolute length
    double min = 0, max = 0;  //!< AbsPerc: the range of the absolute value
    QStringList enumLabels;   //!< Enum: the labels (index = the value in .mlx scripts)
    QString label, tooltip;
    //! Few users change it: MeshLab 2022.02 and later show it only after the dialog's "Show
    //! advanced" button, which keeps the dialog on a 768-pixel screen. MeshLab 2020.09 has no
    //! such button and shows every row.
    bool advanced = false;
};

//! The values a filter runs with, read from each MeshLab's RichParameterList by the glue.
class ParamValues {
public:
    virtual ~ParamValues() = default;
    //! A script may lack parameters added after the first release (read with their defaults).
    virtual bool hasParameter(const char* name) const = 0;
    //! Whether the value is a bool (`adaptive` in scripts from before it was an enum).
    virtual bool isBool(const char* name) const = 0;
    virtual int getInt(const char* name) const = 0;
    virtual double getFloat(const char* name) const = 0;
    virtual bool getBool(const char* name) const = 0;
    virtual int getEnum(const char* name) const = 0;
    virtual double getAbsPerc(const char* name) const = 0;
    virtual MeshModel* getMesh(const char* name) const = 0;  //!< null if none
};

//! The filter log (each MeshLab's plugin logger).
class FilterLog {
public:
    virtual ~FilterLog() = default;
    virtual void info(const QString& text) = 0;
    virtual void warning(const QString& text) = 0;
};

//! What a filter run gives back besides the document: its figures by name, in the order added.
//! The FilterPlugin glue (MeshLab 2022.02 and later) returns them from applyFilter as the
//! std::map<std::string, QVariant> that pymeshlab's apply_filter turns into its dict; MeshLab
//! 2020.09's applyFilter returns a bool, and its glue leaves them unused. Names are pymeshlab's
//! style and the CLI report's keys (lower case, '_'); a figure that was not measured (NaN) is
//! left out, as the CLI's JSON has null there. Numbers and booleans only: pymeshlab's dict drops
//! text (a QString) without a word.
struct FilterOutput {
    struct Value {
        enum Kind { Integer, Real, Boolean };
        std::string key;
        Kind kind = Real;
        double number = 0;  //!< Boolean: 0 / 1
    };
    std::vector<Value> values;

    void addInteger(const std::string& key, long long v) { values.push_back({key, Value::Integer, double(v)}); }
    //! Left out when not finite (not measured).
    void addReal(const std::string& key, double v)
    {
        if (std::isfinite(v)) values.push_back({key, Value::Real, v});
    }
    void addBoolean(const std::string& key, bool v) { values.push_back({key, Value::Boolean, v ? 1.0 : 0.0}); }
};

//! A filter failed for a reason the user can fix: `what()` is the whole message. The glue
//! reports it its MeshLab's way (2020.09: errorMessage and the log; 2022.02: MLException), as
//! plainLogText() of it (log_text.h).
class FilterFailure : public std::runtime_error {
public:
    explicit FilterFailure(const QString& message) : std::runtime_error(message.toStdString()) {}
    QString message() const { return QString::fromStdString(what()); }
};

//! Progress callback of both MeshLabs (vcg::CallBackPos).
using Callback = bool(const int pos, const char* str);

}  // namespace fcvt_plugin
