#pragma once
// One run of a filter: the typed bodies of the three filters over MeshLab's document, with the
// plugin's log. filter_run.cpp holds the field and quality filters and the shared helpers,
// filter_remesh.cpp the remeshing.
#include <QString>

#include "filter_types.h"
#include "field.h"
#include "log_text.h"
#include "mesh.h"
#include "region.h"
#include "remesh.h"

namespace fcvt_plugin {

//! Distance samples per mesh: dense enough for a Hausdorff figure at the meshes' resolution,
//! capped for big ones (the core's choice in remesh()).
inline int distanceSamples(const fieldcvt::TriMesh& a, const fieldcvt::TriMesh& b)
{
    return std::clamp(20 * (a.faceCount() + b.faceCount()), 20000, 200000);
}

//! One filter run: the typed bodies of the three filters, with the plugin's log.
class FilterRun {
public:
    //! `figures`: the caller takes the run's figures (output()); what only they need (the quality
    //! report's count of the layer's field singularities) is computed only then.
    explicit FilterRun(FilterLog& log, bool figures = false) : log_(log), figures_(figures) {}

    bool applyRemesh(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);
    bool applyField(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);
    bool applyQuality(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);
    //! The figures of the run that succeeded (fcvt_filters.h: applyFilter returns them).
    const FilterOutput& output() const { return output_; }

private:
    //! What the remeshing filter takes from the input layer besides the geometry.
    struct RemeshInputs {
        bool densityFromQuality = false;     //!< adaptive: ρ = per-vertex quality
        bool featuresFromSelection = false;  //!< feature lines = border of the face selection
        bool colorIrregular = false;         //!< colour the output's vertices by valence
        bool selectedOnly = false;           //!< remesh only the selected faces (region.h)
    };
    //! The typed body of "Remeshing: Field-Aligned CVT (FCVT)".
    bool remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, const RemeshInputs& inputs, vcg::CallBackPos* cb);
    //! The layer's field, density and selection border the run takes (filter_remesh.cpp).
    void readLayerInputs(MeshModel& input, const fieldcvt::TriMesh& in, const RemeshInputs& inputs, fieldcvt::RemeshParams& run);
    //! The typed body of "Remeshing Quality Report (FCVT)" (`reference` null: no distances).
    bool qualityReport(MeshModel& mesh, MeshModel* reference, bool colorIrregular, vcg::CallBackPos* cb);
    //! The typed body of "Compute 6-RoSy Field" (at most `maxCrosses` crosses drawn).
    bool computeRosyField(MeshDocument& md, const fieldcvt::FieldParams& params, int maxCrosses, vcg::CallBackPos* cb);
    //! Takes back the GUI's "modified" mark on layer `layerId` after this filter (see the .cpp).
    static void keepUnmodified(MeshDocument& md, int layerId);
    //! The field source (0..sources-1: a script may carry any integer as an enum value) and the
    //! seed (0 or more), shared by the remeshing and the field filters; fails otherwise.
    void checkFieldSourceAndSeed(int fieldSource, int sources, int seed)
    {
        if (fieldSource < 0 || fieldSource >= sources)
            fail(QString("FCVT: %1 must be 0..%2 (got %3)").arg(parameterName(kFieldSource)).arg(sources - 1).arg(fieldSource));
        if (seed < 0) fail(QString("FCVT: %1 must be 0 or more (got %2)").arg(parameterName(kSeed)).arg(seed));
    }
    //! Fails the filter: throws FilterFailure(message), which the glue reports.
    [[noreturn]] bool fail(const QString& message) { throw FilterFailure(message); }
    //! The current layer if it holds faces; otherwise fails.
    MeshModel* currentTriangleLayer(MeshDocument& md);
    //! The run's lines in the order its stages ran: repair, field, optimisation, valence, the
    //! new layer and its figures, the times.
    void logReport(const fieldcvt::RemeshResult& result, const fieldcvt::RemeshParams& run, const QString& layerName,
                   const QString& inputName);
    //! The remeshing's figures (output_): the top level of the CLI's --report.
    void addRunFigures(const fieldcvt::RemeshResult& r, double wallSeconds);
    //! The run's region line ("Remesh only selected faces").
    void logRegion(const fieldcvt::RegionRemeshResult& region);
    //! The selected faces of `input`; fails when there are none.
    std::vector<char> selectedFaces(const MeshModel& input);

    //! Log lines (info / warning, shown red in the GUI) through plainLogText(), so that MeshLab's
    //! HTML log shows all of their text.
    void logInfo(const QString& line);
    void logWarning(const QString& line);
    //! The layer's mesh for remeshing or a field (fcvt_plugin::toSurfaceMesh), with the
    //! zero-area triangles it flipped logged.
    //! The layer as the core's mesh, with its file's double coordinates when it is as read, and
    //! the file's triangulation of polygons unless `keepFaces` (face selection in use).
    fieldcvt::TriMesh surfaceOf(const MeshModel& layer, bool keepFaces = false);

    //! The singularities of the layer's per-vertex field `rosy` on `measured` (its live vertices in
    //! order), for the quality report's figures; false (nothing added) when the layer has none.
    bool layerFieldSingularities(MeshModel& layer, const fieldcvt::TriMesh& measured, int& count, int& indexSum);

    FilterLog& log_;
    bool figures_ = false;
    FilterOutput output_;
    QStringList warnings_;  //!< the warning lines logged so far, in order (the remeshing's "warnings")
};

}  // namespace fcvt_plugin
