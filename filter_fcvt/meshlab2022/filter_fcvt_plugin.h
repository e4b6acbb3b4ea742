#pragma once
// MeshLab 2022.02 glue (Debian 13): the FilterPlugin interface over the MeshLab-neutral filters
// of fcvt_filters.h. Parameters are declared from their neutral definitions, applyFilter runs
// the filter and turns a failure into the MLException MeshLab 2022.02 expects.
#include <common/plugins/interfaces/filter_plugin.h>

class FilterFcvtPlugin : public QObject, public FilterPlugin {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)

public:
    FilterFcvtPlugin();

    QString pluginName() const override;
    QString filterName(ActionIDType filter) const override;
    QString filterInfo(ActionIDType filter) const override;
    FilterClass getClass(const QAction* a) const override;
    FilterArity filterArity(const QAction* a) const override;
    int getRequirements(const QAction* a) override;
    int getPreConditions(const QAction* a) const override;
    int postCondition(const QAction* a) const override;
    // Both overloads: the base class's MeshDocument one would dereference md.mm() even when no
    // mesh is loaded.
    RichParameterList initParameterList(const QAction* a, const MeshModel& m) override;
    RichParameterList initParameterList(const QAction* a, const MeshDocument& md) override;
    std::map<std::string, QVariant> applyFilter(const QAction* a, const RichParameterList& par, MeshDocument& md,
                                                unsigned int& postConditionMask, vcg::CallBackPos* cb) override;
};
