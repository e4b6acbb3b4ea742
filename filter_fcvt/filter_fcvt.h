#pragma once
// MeshLab 2020.09 filter plugin for FCVT remeshing. A thin adapter: it reads the parameters,
// converts CMeshO <-> fieldcvt::TriMesh, calls fieldcvt::remesh and reports; no algorithm lives here.
#include <common/interfaces.h>

#include "remesh.h"

class FilterFcvtPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_FCVT_REMESH };

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
    bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                     vcg::CallBackPos* cb) override;

    // The parameter names are frozen API: they are the keys of .mlx scripts.
    static constexpr const char* kVertexCount = "vertexCount";
    static constexpr const char* kLambda = "lambda";
    static constexpr const char* kCvtIterations = "cvtIterations";
    static constexpr const char* kFcvtIterations = "fcvtIterations";
    static constexpr const char* kSeed = "seed";

private:
    //! The typed body of "Remeshing: Field-Aligned CVT (FCVT)".
    void addParameters(QAction* a, int vertexCountDefault, RichParameterList& par);
    bool remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, vcg::CallBackPos* cb);
    //! Fails the filter: sets errorMessage and also logs it, because meshlabserver 2020.09 prints
    //! the filter log but never errorMsg().
    bool fail(const QString& message);
    void logReport(const fieldcvt::RemeshResult& result, const QString& layerName);
};
