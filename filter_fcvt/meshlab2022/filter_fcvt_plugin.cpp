#include "filter_fcvt_plugin.h"

#include "../plugin_glue.h"

#include <map>
#include <string>

namespace {

// MeshLab 2023.12 renamed RichAbsPerc to RichPercentage (same constructor, same .mlx value);
// 2022.02 has the old name. The rest of the FilterPlugin API is the same in 2022.02-2025.07.
#if __has_include(<common/parameters/rich_parameter/rich_percentage.h>)
using AbsoluteOrPercentParameter = RichPercentage;
#else
using AbsoluteOrPercentParameter = RichAbsPerc;
#endif

using fcvt_plugin::glue::filterId;

// The neutral parameter definitions as MeshLab 2022.02's (and later) Rich* parameters.
RichParameterList toRichParameters(const std::vector<fcvt_plugin::ParamDef>& defs, const MeshDocument* md,
                                   const MeshModel* current)
{
    using fcvt_plugin::ParamDef;
    RichParameterList list;
    for (const ParamDef& p : defs) {
        switch (p.type) {
        case ParamDef::Int: list.addParam(RichInt(p.name, int(p.value), p.label, p.tooltip, p.advanced)); break;
        case ParamDef::Float: list.addParam(RichFloat(p.name, Scalarm(p.value), p.label, p.tooltip, p.advanced)); break;
        case ParamDef::Bool: list.addParam(RichBool(p.name, p.value != 0, p.label, p.tooltip, p.advanced)); break;
        case ParamDef::Enum: list.addParam(RichEnum(p.name, int(p.value), p.enumLabels, p.label, p.tooltip, p.advanced)); break;
        case ParamDef::AbsPerc:
            list.addParam(AbsoluteOrPercentParameter(p.name, Scalarm(p.value), Scalarm(p.min), Scalarm(p.max), p.label, p.tooltip,
                                                     p.advanced));
            break;
        case ParamDef::Mesh:
            // The default is the current layer (the measured layer itself: no distances).
            list.addParam(RichMesh(p.name, current != nullptr ? unsigned(current->id()) : 0u, md, p.label, p.tooltip));
            break;
        }
    }
    return list;
}

// A mesh parameter holds the layer's id in the document.
class Values : public fcvt_plugin::glue::RichValues<RichParameterList> {
public:
    Values(const RichParameterList& par, MeshDocument& md) : RichValues(par), md_(md) {}
    MeshModel* getMesh(const char* name) const override { return md_.getMesh(par_.getMeshId(name)); }

private:
    MeshDocument& md_;
};

class Log : public fcvt_plugin::FilterLog {
public:
    explicit Log(const FilterPlugin& plugin) : plugin_(plugin) {}
    void info(const QString& text) override { plugin_.log(GLLogStream::FILTER, text.toStdString()); }
    void warning(const QString& text) override { plugin_.log(GLLogStream::WARNING, text.toStdString()); }

private:
    const FilterPlugin& plugin_;
};

// The figures of a run as applyFilter's return value, which pymeshlab's apply_filter returns as
// a dict (it converts int, double, bool and MeshLab's vector and matrix types).
std::map<std::string, QVariant> toVariantMap(const fcvt_plugin::FilterOutput& output)
{
    using Value = fcvt_plugin::FilterOutput::Value;
    std::map<std::string, QVariant> map;
    for (const Value& v : output.values) {
        switch (v.kind) {
        case Value::Integer: map[v.key] = QVariant(int(v.number)); break;
        case Value::Real: map[v.key] = QVariant(v.number); break;
        case Value::Boolean: map[v.key] = QVariant(v.number != 0); break;
        }
    }
    return map;
}

}  // namespace

FilterFcvtPlugin::FilterFcvtPlugin()
{
    for (fcvt_plugin::FilterId id : fcvt_plugin::kFilterIds) typeList.push_back(id);
    for (ActionIDType tt : types()) actionList.push_back(new QAction(filterName(tt), this));
}

QString FilterFcvtPlugin::pluginName() const { return fcvt_plugin::pluginName(); }

QString FilterFcvtPlugin::filterName(ActionIDType filter) const { return fcvt_plugin::filterName(filterId(filter)); }

QString FilterFcvtPlugin::filterInfo(ActionIDType filter) const { return fcvt_plugin::filterInfo(filterId(filter)); }

FilterPlugin::FilterClass FilterFcvtPlugin::getClass(const QAction* a) const
{
    return fcvt_plugin::glue::filterClass<FilterPlugin>(filterId(ID(a)));
}

FilterPlugin::FilterArity FilterFcvtPlugin::filterArity(const QAction*) const { return SINGLE_MESH; }

int FilterFcvtPlugin::getRequirements(const QAction*) { return MeshModel::MM_NONE; }

int FilterFcvtPlugin::getPreConditions(const QAction* a) const { return fcvt_plugin::preConditions(filterId(ID(a))); }

int FilterFcvtPlugin::postCondition(const QAction* a) const { return fcvt_plugin::postCondition(filterId(ID(a))); }

RichParameterList FilterFcvtPlugin::initParameterList(const QAction* a, const MeshModel& m)
{
    return toRichParameters(fcvt_plugin::parameters(filterId(ID(a)), &m), nullptr, &m);
}

RichParameterList FilterFcvtPlugin::initParameterList(const QAction* a, const MeshDocument& md)
{
    return toRichParameters(fcvt_plugin::parameters(filterId(ID(a)), md.mm()), &md, md.mm());
}

std::map<std::string, QVariant> FilterFcvtPlugin::applyFilter(const QAction* a, const RichParameterList& par, MeshDocument& md,
                                                              unsigned int&, vcg::CallBackPos* cb)
{
    // MeshLab 2022.02 reports a failed filter by the MLException it throws (the GUI shows its
    // text, pymeshlab raises it); anything else would end the application. The message also goes
    // to the log, as in the 2020.09 plugin. A run that succeeded returns its figures (pymeshlab's
    // dict; MeshLab's GUI does not show them, its log has them).
    Log log(*this);
    const Values values(par, md);
    QString failure;
    fcvt_plugin::FilterOutput output;
    if (fcvt_plugin::runFilter(filterId(ID(a)), md, values, log, cb, failure, &output)) return toVariantMap(output);
    throw MLException(failure);
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterFcvtPlugin)
