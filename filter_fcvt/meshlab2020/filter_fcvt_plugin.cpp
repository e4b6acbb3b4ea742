#include "filter_fcvt_plugin.h"

#include <exception>
#include <functional>
#include <string>

#include "../fcvt_filters.h"
#include "../log_text.h"

namespace {

fcvt_plugin::FilterId filterId(int id) { return static_cast<fcvt_plugin::FilterId>(id); }

// The neutral parameter definitions as MeshLab 2020.09's Rich* parameters.
void addRichParameters(const std::vector<fcvt_plugin::ParamDef>& defs, MeshDocument* md, MeshModel* current,
                       RichParameterList& list)
{
    using fcvt_plugin::ParamDef;
    for (const ParamDef& p : defs) {
        switch (p.type) {
        case ParamDef::Int: list.addParam(RichInt(p.name, int(p.value), p.label, p.tooltip)); break;
        case ParamDef::Float: list.addParam(RichFloat(p.name, float(p.value), p.label, p.tooltip)); break;
        case ParamDef::Bool: list.addParam(RichBool(p.name, p.value != 0, p.label, p.tooltip)); break;
        case ParamDef::Enum: list.addParam(RichEnum(p.name, int(p.value), p.enumLabels, p.label, p.tooltip)); break;
        case ParamDef::AbsPerc:
            list.addParam(RichAbsPerc(p.name, float(p.value), float(p.min), float(p.max), p.label, p.tooltip));
            break;
        case ParamDef::Mesh:
            // The default is the current layer (the measured layer itself: no distances).
            if (md != nullptr && current != nullptr)
                list.addParam(RichMesh(p.name, current, md, p.label, p.tooltip));
            else  // no document: a parameter without a mesh (only for completeness of the overload)
                list.addParam(RichMesh(p.name, static_cast<MeshModel*>(nullptr), nullptr, p.label, p.tooltip));
            break;
        }
    }
}

class Values : public fcvt_plugin::ParamValues {
public:
    explicit Values(const RichParameterList& par) : par_(par) {}
    bool hasParameter(const char* name) const override { return par_.hasParameter(name); }
    bool isBool(const char* name) const override { return par_.getParameterByName(name).value().isBool(); }
    int getInt(const char* name) const override { return par_.getInt(name); }
    double getFloat(const char* name) const override { return fcvt_plugin::typedValue(par_.getFloat(name)); }
    bool getBool(const char* name) const override { return par_.getBool(name); }
    int getEnum(const char* name) const override { return par_.getEnum(name); }
    double getAbsPerc(const char* name) const override { return fcvt_plugin::typedValue(par_.getAbsPerc(name)); }
    MeshModel* getMesh(const char* name) const override { return par_.getMesh(name); }

private:
    const RichParameterList& par_;
};

}  // namespace

// MeshFilterInterface::Log is protected: the log adapter lives in the plugin's scope.
class FilterFcvtPluginLog : public fcvt_plugin::FilterLog {
public:
    explicit FilterFcvtPluginLog(std::function<void(bool, const std::string&)> log) : log_(std::move(log)) {}
    void info(const QString& text) override { log_(false, text.toStdString()); }
    void warning(const QString& text) override { log_(true, text.toStdString()); }

private:
    std::function<void(bool warning, const std::string&)> log_;
};

FilterFcvtPlugin::FilterFcvtPlugin()
{
    for (fcvt_plugin::FilterId id : fcvt_plugin::kFilterIds) typeList << id;
    for (FilterIDType tt : types()) actionList << new QAction(filterName(tt), this);
}

QString FilterFcvtPlugin::pluginName() const { return fcvt_plugin::pluginName(); }

QString FilterFcvtPlugin::filterName(FilterIDType filter) const { return fcvt_plugin::filterName(filterId(filter)); }

QString FilterFcvtPlugin::filterInfo(FilterIDType filter) const { return fcvt_plugin::filterInfo(filterId(filter)); }

MeshFilterInterface::FilterClass FilterFcvtPlugin::getClass(QAction* a)
{
    switch (fcvt_plugin::filterKind(filterId(ID(a)))) {
    case fcvt_plugin::FilterKind::Remeshing: return MeshFilterInterface::Remeshing;
    case fcvt_plugin::FilterKind::Normal: return MeshFilterInterface::Normal;
    case fcvt_plugin::FilterKind::MeasureAndVertexColouring:
    default: return FilterClass(MeshFilterInterface::Measure | MeshFilterInterface::VertexColoring);
    }
}

MeshFilterInterface::FILTER_ARITY FilterFcvtPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

int FilterFcvtPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterFcvtPlugin::getPreConditions(QAction* a) const { return fcvt_plugin::preConditions(filterId(ID(a))); }

int FilterFcvtPlugin::postCondition(QAction* a) const { return fcvt_plugin::postCondition(filterId(ID(a))); }

void FilterFcvtPlugin::initParameterSet(QAction* a, MeshModel& m, RichParameterList& par)
{
    addRichParameters(fcvt_plugin::parameters(filterId(ID(a)), &m), nullptr, &m, par);
}

void FilterFcvtPlugin::initParameterSet(QAction* a, MeshDocument& md, RichParameterList& par)
{
    addRichParameters(fcvt_plugin::parameters(filterId(ID(a)), md.mm()), &md, md.mm(), par);
}

bool FilterFcvtPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb)
{
    // Nothing may escape into MeshLab: the GUI catches only std::bad_alloc and meshlabserver
    // nothing at all, so an exception would terminate the application.
    FilterFcvtPluginLog log([this](bool warning, const std::string& text) {
        if (warning)
            Log(GLLogStream::WARNING, text);
        else
            Log(text);
    });
    try {
        const Values values(par);
        fcvt_plugin::applyFilter(filterId(ID(a)), md, values, log, cb);
        return true;
    } catch (const fcvt_plugin::FilterFailure& e) {
        return fail(e.message());
    } catch (const std::exception& e) {
        return fail(fcvt_plugin::unexpectedFailure(&e));
    } catch (...) {
        return fail(fcvt_plugin::unexpectedFailure(nullptr));
    }
}

bool FilterFcvtPlugin::fail(const QString& message)
{
    errorMessage = fcvt_plugin::plainLogText(message);
    Log(GLLogStream::WARNING, errorMessage.toStdString());
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterFcvtPlugin)
