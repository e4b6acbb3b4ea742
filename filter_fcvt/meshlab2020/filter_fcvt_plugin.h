#pragma once
// MeshLab 2020.09 glue (Debian 12): the MeshFilterInterface over the MeshLab-neutral filters of
// fcvt_filters.h. Parameters are declared from their neutral definitions; applyFilter runs the
// filter and reports a failure through errorMessage and the log (meshlabserver 2020.09 prints
// the filter log but never errorMsg()), returning false.
#include <common/interfaces.h>

class FilterFcvtPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    FilterFcvtPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction* a) override;
    FILTER_ARITY filterArity(QAction* a) const override;
    int getRequirements(QAction* a) override;
    int getPreConditions(QAction* a) const override;
    int postCondition(QAction* a) const override;
    // Both overloads: meshlabserver calls the MeshDocument one, which in the base class would
    // dereference md.mm() even when no mesh is loaded.
    void initParameterSet(QAction* a, MeshModel& m, RichParameterList& par) override;
    void initParameterSet(QAction* a, MeshDocument& md, RichParameterList& par) override;
    bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) override;
};
