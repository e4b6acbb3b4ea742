#include "filter_fcvt_plugin.h"

#include <functional>
#include <string>

#include "../plugin_glue.h"

namespace {

using fcvt_plugin::glue::filterId;

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

// A mesh parameter holds the layer itself.
class Values : public fcvt_plugin::glue::RichValues<RichParameterList> {
public:
    using RichValues::RichValues;
    MeshModel* getMesh(const char* name) const override { return par_.getMesh(name); }
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
    return fcvt_plugin::glue::filterClass<MeshFilterInterface>(filterId(ID(a)));
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
    FilterFcvtPluginLog log([this](bool warning, const std::string& text) {
        if (warning)
            Log(GLLogStream::WARNING, text);
        else
            Log(text);
    });
    const Values values(par);
    QString failure;
    if (fcvt_plugin::runFilter(filterId(ID(a)), md, values, log, cb, failure)) return true;
    errorMessage = failure;  // logged too: meshlabserver 2020.09 prints the log but never errorMsg()
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterFcvtPlugin)
