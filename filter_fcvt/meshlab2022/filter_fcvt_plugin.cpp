#include "filter_fcvt_plugin.h"

#include <exception>

#include "../fcvt_filters.h"
#include "../log_text.h"

namespace {

// MeshLab 2023.12 renamed RichAbsPerc to RichPercentage (same constructor, same .mlx value);
// 2022.02 has the old name. The rest of the FilterPlugin API is the same in 2022.02-2025.07.
#if __has_include(<common/parameters/rich_parameter/rich_percentage.h>)
using AbsoluteOrPercentParameter = RichPercentage;
#else
using AbsoluteOrPercentParameter = RichAbsPerc;
#endif

fcvt_plugin::FilterId filterId(int id) { return static_cast<fcvt_plugin::FilterId>(id); }

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

class Values : public fcvt_plugin::ParamValues {
public:
    Values(const RichParameterList& par, MeshDocument& md) : par_(par), md_(md) {}
    bool hasParameter(const char* name) const override { return par_.hasParameter(name); }
    bool isBool(const char* name) const override { return par_.getParameterByName(name).value().isBool(); }
    int getInt(const char* name) const override { return par_.getInt(name); }
    double getFloat(const char* name) const override { return fcvt_plugin::typedValue(par_.getFloat(name)); }
    bool getBool(const char* name) const override { return par_.getBool(name); }
    int getEnum(const char* name) const override { return par_.getEnum(name); }
    double getAbsPerc(const char* name) const override { return fcvt_plugin::typedValue(par_.getAbsPerc(name)); }
    MeshModel* getMesh(const char* name) const override { return md_.getMesh(par_.getMeshId(name)); }

private:
    const RichParameterList& par_;
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
    switch (fcvt_plugin::filterKind(filterId(ID(a)))) {
    case fcvt_plugin::FilterKind::Remeshing: return FilterPlugin::Remeshing;
    case fcvt_plugin::FilterKind::Normal: return FilterPlugin::Normal;
    case fcvt_plugin::FilterKind::MeasureAndVertexColouring:
    default: return FilterClass(FilterPlugin::Measure | FilterPlugin::VertexColoring);
    }
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
    // to the log, as in the 2020.09 plugin.
    Log log(*this);
    QString failure;
    try {
        Values values(par, md);
        fcvt_plugin::applyFilter(filterId(ID(a)), md, values, log, cb);
        return {};
    } catch (const fcvt_plugin::FilterFailure& e) {
        failure = e.message();
    } catch (const std::exception& e) {
        failure = fcvt_plugin::unexpectedFailure(&e);
    } catch (...) {
        failure = fcvt_plugin::unexpectedFailure(nullptr);
    }
    failure = fcvt_plugin::plainLogText(failure);
    log.warning(failure);
    throw MLException(failure);
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterFcvtPlugin)
