#pragma once
// MeshLab 2020.09 filter plugin for FCVT remeshing, its 6-RoSy field and a quality report. A thin
// adapter: it reads the parameters, converts CMeshO <-> fieldcvt::TriMesh, calls the core
// (fieldcvt::remesh, fieldcvt::computeField, fieldcvt::computeQuality) and reports; no algorithm
// lives here.
#include <common/interfaces.h>

#include "field.h"
#include "remesh.h"

class FilterFcvtPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_FCVT_REMESH, FP_FCVT_FIELD, FP_FCVT_QUALITY };

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
    static constexpr const char* kFieldSource = "fieldSource";
    static constexpr const char* kSeed = "seed";
    static constexpr const char* kSizeMode = "sizeMode";
    static constexpr const char* kTargetLength = "targetLength";
    static constexpr const char* kValenceOptimization = "valenceOptimization";
    static constexpr const char* kFeatureAngle = "featureAngle";
    static constexpr const char* kFeatureSelection = "featureSelection";
    static constexpr const char* kAdaptive = "adaptive";
    //! Remeshing (default off) and quality report (default on): colour vertices by valence.
    static constexpr const char* kColorIrregular = "colorIrregular";
    //! Remeshing: repair the input first (repair.h); off = the strict check only.
    static constexpr const char* kRepair = "repair";
    //! Quality report: the layer d_RMS / d_H are measured against (itself = no distances).
    static constexpr const char* kReferenceLayer = "referenceLayer";
    //! Name of the per-vertex Point3m attribute that holds a 6-RoSy field (representative d).
    static constexpr const char* kRosyAttribute = "rosy";
    //! Label of the layer "Compute 6-RoSy Field" adds (MeshLab appends "(1)", ... if taken).
    static constexpr const char* kFieldLayerLabel = "6-RoSy field";

private:
    //! `md` may be null (the MeshModel overload), and so may `m` (no mesh loaded).
    void addParameters(QAction* a, MeshDocument* md, MeshModel* m, RichParameterList& par);
    //! Parameters -> typed arguments, then the typed body of each filter.
    bool applyRemesh(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
    bool applyField(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
    bool applyQuality(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
    //! What the remeshing filter takes from the input layer besides the geometry.
    struct RemeshInputs {
        bool densityFromQuality = false;  //!< adaptive: ρ = per-vertex quality
        bool featuresFromSelection = false;  //!< feature lines = border of the face selection
        bool colorIrregular = false;      //!< colour the output's vertices by valence
    };
    //! The typed body of "Remeshing: Field-Aligned CVT (FCVT)".
    bool remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, const RemeshInputs& inputs,
                    vcg::CallBackPos* cb);
    //! The typed body of "Remeshing Quality Report (FCVT)" (`reference` null: no distances).
    bool qualityReport(MeshModel& mesh, MeshModel* reference, bool colorIrregular, vcg::CallBackPos* cb);
    //! The typed body of "Compute 6-RoSy Field".
    bool computeRosyField(MeshDocument& md, const fieldcvt::FieldParams& params, vcg::CallBackPos* cb);
    //! Fails the filter: sets errorMessage and also logs it, because meshlabserver 2020.09 prints
    //! the filter log but never errorMsg().
    bool fail(const QString& message);
    //! The current layer if it holds faces; otherwise nullptr, with errorMessage set.
    MeshModel* currentTriangleLayer(MeshDocument& md);
    void logReport(const fieldcvt::RemeshResult& result, const QString& layerName);
};
