// The field and quality filters, and the helpers every filter run shares (filter_run.h); the
// remeshing is filter_remesh.cpp.
#include "filter_run.h"

#include <vcg/complex/allocate.h>

#include <QApplication>
#include <QFileInfo>
#include <QPointer>
#include <QTimer>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "closest_point.h"
#include "errors.h"
#include "field_of_input.h"
#include "field.h"
#include "field_drawing.h"
#include "filter_parameters.h"
#include "layer_data.h"
#include "log_text.h"
#include "mesh_check.h"
#include "mesh_convert.h"
#include "metrics.h"
#include "progress.h"
#include "remesh.h"
#include "valence_colour.h"
#include "working_frame.h"

namespace fcvt_plugin {

namespace {

//! The Table 2 figures by the CLI report's keys (cli/report.cpp, metricsJson), distances apart.
void addQualityFigures(const fieldcvt::QualityMetrics& m, FilterOutput& out)
{
    out.addReal("q_min", m.qMin);
    out.addReal("q_avg", m.qAvg);
    out.addReal("theta_min", m.thetaMin);
    out.addReal("theta_min_avg", m.thetaMinAvg);
    out.addReal("theta_max", m.thetaMax);
    out.addReal("pct_lt30", m.pctLt30);
    out.addReal("pct_gt90", m.pctGt90);
    out.addReal("v6_pct", m.v6Pct);
    out.addReal("boundary_v4_pct", m.boundaryV4Pct);  // left out on a closed mesh (NaN)
}

}  // namespace

bool FilterRun::applyQuality(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb)
{
    MeshModel* mesh = currentTriangleLayer(md);
    if (mesh == nullptr) return false;
    MeshModel* reference = par.getMesh(kReferenceLayer);
    return qualityReport(*mesh, reference == mesh ? nullptr : reference, par.getBool(kColorIrregular), cb);
}

bool FilterRun::applyField(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb)
{
    const int fieldSource = par.getEnum(kFieldSource);
    const int seed = par.getInt(kSeed);
    checkFieldSourceAndSeed(fieldSource, kComputedFieldSources, seed);

    fieldcvt::FieldParams params;
    params.source = kFieldSources[fieldSource].source;
    params.seed = static_cast<std::uint64_t>(seed);
    const int maxCrosses = par.hasParameter(kMaxCrosses) ? par.getInt(kMaxCrosses) : kDefaultMaxCrosses;
    if (maxCrosses < 1)
        return fail(QString("FCVT: %1 must be at least 1 (got %2)").arg(parameterName(kMaxCrosses)).arg(maxCrosses));
    return computeRosyField(md, params, maxCrosses, cb);
}

MeshModel* FilterRun::currentTriangleLayer(MeshDocument& md)
{
    MeshModel* input = md.mm();
    if (input == nullptr) {
        fail("FCVT: no mesh loaded");
        return nullptr;
    }
    if (input->cm.fn == 0) {
        fail(QString("FCVT: layer '%1' has no faces; a triangle mesh is required").arg(input->label()));
        return nullptr;
    }
    return input;
}

fieldcvt::TriMesh FilterRun::surfaceOf(const MeshModel& layer, bool keepFaces)
{
    int flipped = 0;
    fieldcvt::TriMesh mesh = fcvt_plugin::toSurfaceMesh(layer.cm, flipped);
    // The coordinates the command line would read from the same file.
    std::vector<fieldcvt::Face> fileFaces;
    const fcvt_plugin::FilePrecision precision =
        fcvt_plugin::fullPrecisionCoordinates(layer.fullName().toStdString(), mesh, &fileFaces);
    // MeshLab's PLY importer fans polygons from their first corner, which folds concave ones (a C
    // shape's cap came out at 1.6 times its area, a lobed one lost 512 of 1196 triangles): the
    // readers' triangulation instead, when the layer is the file's (its vertices as read).
    if (!keepFaces && !fileFaces.empty() && fileFaces != mesh.faces) {
        mesh.faces = std::move(fileFaces);
        flipped = 0;  // the readers' triangles have no zero-area fan triangle to flip
        logInfo(QString("FCVT input: the polygons of '%1' triangulated as the command line does (MeshLab's fans "
                        "fold concave polygons)")
                    .arg(layer.fullName()));
    }
    if (precision == fcvt_plugin::FilePrecision::Restored)
        logInfo(QString("FCVT input: the double-precision coordinates of '%1' (MeshLab holds them in single precision; "
                        "the layer is as it was read), as the command line reads them")
                    .arg(layer.fullName()));
    else if (precision == fcvt_plugin::FilePrecision::NotTheFile && sizeof(Scalarm) == sizeof(float))
        logInfo(QString("FCVT input: the layer's single-precision coordinates ('%1' differs from the layer: edited "
                        "since it was read?); the command line, reading the file, may give another mesh")
                    .arg(layer.fullName()));
    if (flipped > 0)
        logWarning(QString("FCVT input: flipped %1 zero-area triangles of '%2' into their neighbours (a fan "
                           "over a polygon's straight corner; removing them would tear the surface)")
                       .arg(flipped)
                       .arg(layer.label()));
    return mesh;
}

bool FilterRun::computeRosyField(MeshDocument& md, const fieldcvt::FieldParams& params, int maxCrosses, vcg::CallBackPos* cb)
{
    MeshModel* input = currentTriangleLayer(md);
    if (input == nullptr) return false;
    const bool inputWasModified = input->meshModified();

    if (cb != nullptr) cb(0, "checking the input");
    const fieldcvt::TriMesh in = surfaceOf(*input);
    if (cb != nullptr) cb(10, "computing the 6-RoSy field");
    // As `fcvt field` and the remeshing do: on the surface centred and scaled to unit cells.
    const fieldcvt::InputField computed = fieldcvt::fieldOfInput(in, params);
    const fieldcvt::InputReport& report = computed.report;
    const fieldcvt::TriMesh& clean = computed.clean;
    const fieldcvt::DirectionField& field = computed.field;
    const std::vector<fieldcvt::Singularity>& singularities = computed.singularities;

    // Everything is computed: now change the document. The drawing layer is removed again if
    // filling it fails; the attribute is written last.
    if (cb != nullptr) cb(90, "drawing the field");
    MeshModel* drawing = md.addNewMesh("", kFieldLayerLabel, false);
    fcvt_plugin::FieldDrawingStats stats;
    try {
        stats = fcvt_plugin::drawField(clean, field, drawing->cm, maxCrosses);
        drawing->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_COLOR);
        drawing->cm.Tr = input->cm.Tr;
        updateBoxAndNormals(*drawing);
    } catch (...) {
        removeLayer(md, drawing);
        md.setCurrentMesh(input->id());
        throw;
    }

    auto rosy = pointAttribute(input->cm, kRosyAttribute);
    size_t live = 0;
    for (auto vi = input->cm.vert.begin(); vi != input->cm.vert.end(); ++vi) {
        if (vi->IsD()) continue;
        const int c = report.cleanIndex[live++];
        rosy[vi] = c >= 0 ? toPoint3m(field.directions[size_t(c)]) : Point3m(0, 0, 0);
    }
    if (cb != nullptr) cb(100, "6-RoSy field done");
    if (!inputWasModified) keepUnmodified(md, input->id());

    // What the input check would repair is not an error here: the layer is not changed, the
    // field just leaves those elements out (information, not a warning).
    const QStringList ignored = fcvt_plugin::fieldIgnoredText(report);
    if (!ignored.isEmpty())
        logInfo(
            QString("FCVT field: the layer '%1' is unchanged; the field leaves out %2").arg(input->label(), ignored.join("; ")));
    logInfo(QString("FCVT field: %1 (seed %2) on layer '%3': %4; stored as the per-vertex attribute "
                    "'%5'")
                .arg(kFieldSources[fieldSourceIndex(params.source)].label)
                .arg(qulonglong(params.seed))
                .arg(input->label())
                .arg(singularitySummary(singularities, fieldcvt::computeTopology(clean)))
                .arg(kRosyAttribute));
    logInfo(QString("FCVT field: new layer '%1': crosses at %2 of %3 vertices (%4 at most%5), "
                    "segments %6 long on average (mean edge %7), lifted %8 x their length off the "
                    "surface")
                .arg(drawing->label())
                .arg(stats.drawnVertices)
                .arg(clean.vertexCount())
                .arg(maxCrosses)
                .arg(stats.spacing > 0 ? QString(", one per grid cell of %1").arg(num(stats.spacing)) : QString(", every vertex"))
                .arg(num(stats.meanSegmentLength))
                .arg(num(stats.meanEdgeLength))
                .arg(fcvt_plugin::kLift));
    // As `fcvt field` prints them: on the surface the field was computed on (the layer as the
    // input check leaves it).
    int indexSum = 0;
    for (const fieldcvt::Singularity& s : singularities) indexSum += s.index;
    output_.addInteger("singularities", static_cast<int>(singularities.size()));
    output_.addInteger("index_sum", indexSum);
    output_.addInteger("field_vertices", clean.vertexCount());
    output_.addInteger("drawn_crosses", stats.drawnVertices);
    return true;
}

void FilterRun::keepUnmodified(MeshDocument& md, int layerId)
{
    // MeshLab 2020.09's GUI marks the current layer modified after every filter that succeeds
    // (MainWindow::executeFilter: meshDoc()->mm()->setMeshModified()). The field filter only
    // adds the attribute `rosy` to it, so the mark is taken back once control returns to the
    // event loop, and the layer list is redrawn (its public slot updateLayerDialog). Without an
    // event loop (meshlabserver) this never runs, and nothing needs it.
    QPointer<MeshDocument> document(&md);
    QTimer::singleShot(0, qApp, [document, layerId]() {
        if (document.isNull()) return;
        if (MeshModel* m = document->getMesh(layerId)) m->setMeshModified(false);
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->inherits("MainWindow")) QMetaObject::invokeMethod(w, "updateLayerDialog", Qt::QueuedConnection);
    });
}

bool FilterRun::qualityReport(MeshModel& mesh, MeshModel* reference, bool colorIrregular, vcg::CallBackPos* cb)
{
    if (reference != nullptr && reference->cm.fn == 0)
        return fail(QString("FCVT: the reference layer '%1' has no faces; choose a triangle mesh, or "
                            "the measured layer itself for no distances")
                        .arg(reference->label()));
    if (cb != nullptr) cb(0, "FCVT: measuring quality");
    const fieldcvt::TriMesh measured = fcvt_plugin::toTriMesh(mesh.cm);
    const fieldcvt::QualityMetrics quality = fieldcvt::computeQuality(measured);
    const fieldcvt::TopologySummary topology = fieldcvt::computeTopology(measured);
    fieldcvt::DistanceMetrics distance;
    double boundaryDistance = std::numeric_limits<double>::quiet_NaN();
    if (reference != nullptr) {
        if (cb != nullptr) cb(20, "FCVT: measuring distances");
        const fieldcvt::TriMesh ref = fcvt_plugin::toTriMesh(reference->cm);
        distance = fieldcvt::computeDistance(measured, ref, distanceSamples(measured, ref));
        boundaryDistance = fieldcvt::boundaryDistance(measured, ref);  // NaN without open boundaries
    }
    // Measured before anything changes: a failure above leaves the layer as it was.
    QString colours;
    if (colorIrregular) colours = applyValenceColours(measured, mesh);
    if (cb != nullptr) cb(100, "FCVT: quality report done");

    logInfo(QString("FCVT quality of '%1': %2 vertices, %3 faces").arg(mesh.label()).arg(quality.vertices).arg(quality.faces));
    logInfo("FCVT quality: " + qualityText(quality));
    if (reference != nullptr) {
        logInfo(QString("FCVT quality: d_RMS %1, d_H %2 (fractions of the bounding-box diagonal of '%3')")
                    .arg(num(distance.rms))
                    .arg(num(distance.hausdorff))
                    .arg(reference->label()));
        if (mesh.cm.Tr != reference->cm.Tr)
            logWarning(QString("FCVT quality: '%1' and '%2' have different transformation matrices; the "
                               "distances are between the stored coordinates")
                           .arg(mesh.label(), reference->label()));
    } else {
        logInfo("FCVT quality: d_RMS and d_H not measured (the reference layer is the measured layer)");
    }
    logInfo("FCVT quality topology: " + topologyText(topology));
    if (colorIrregular) logInfo("FCVT valence colours: " + colours);

    // The same figures by name, as `fcvt metrics --json` has them (plus the topology).
    FilterOutput& out = output_;
    out.addInteger("vertices", quality.vertices);
    out.addInteger("faces", quality.faces);
    addQualityFigures(quality, out);
    if (reference != nullptr) {
        out.addReal("d_rms", distance.rms);
        out.addReal("d_h", distance.hausdorff);
        out.addReal("d_boundary", boundaryDistance);
    }
    out.addInteger("genus", topology.genus);
    out.addInteger("boundary_loops", topology.boundaryLoops);
    out.addInteger("components", topology.components);
    out.addBoolean("manifold", topology.manifold());
    out.addBoolean("orientable", topology.orientable);
    int singularities = 0, indexSum = 0;
    if (figures_ && layerFieldSingularities(mesh, measured, singularities, indexSum)) {
        out.addInteger("singularities", singularities);
        out.addInteger("index_sum", indexSum);
        logInfo(QString("FCVT quality: the layer's field '%1': %2 singularities, index sum %3 (in sixths of a turn)")
                    .arg(kRosyAttribute)
                    .arg(singularities)
                    .arg(indexSum));
    }
    return true;
}

bool FilterRun::layerFieldSingularities(MeshModel& layer, const fieldcvt::TriMesh& measured, int& count, int& indexSum)
{
    auto rosy = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(layer.cm, kRosyAttribute);
    if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(layer.cm, rosy)) return false;
    std::vector<fieldcvt::Vec3> vectors;
    vectors.reserve(measured.vertices.size());
    for (auto vi = layer.cm.vert.begin(); vi != layer.cm.vert.end(); ++vi)
        if (!vi->IsD()) vectors.push_back(toVec3(rosy[vi]));
    if (vectors.size() != measured.vertices.size()) return false;
    try {
        // Each vector on its vertex's tangent plane; (nearly) normal or zero ones (vertices on no
        // face) get the smooth field's direction there.
        const fieldcvt::DirectionField field = fieldcvt::fieldFromVectors(measured, vectors);
        const std::vector<fieldcvt::Singularity> found = fieldcvt::findSingularities(measured, field);
        count = static_cast<int>(found.size());
        indexSum = 0;
        for (const fieldcvt::Singularity& s : found) indexSum += s.index;
        return true;
    } catch (const fieldcvt::InvalidInputError& e) {
        logInfo(QString("FCVT quality: the layer's field '%1' is not counted: %2")
                    .arg(kRosyAttribute, QString::fromStdString(e.what())));
        return false;
    }
}

void FilterRun::logInfo(const QString& line) { log_.info(plainLogText(line)); }

void FilterRun::logWarning(const QString& line)
{
    const QString text = plainLogText(line);
    warnings_.push_back(text);
    log_.warning(text);
}

}  // namespace fcvt_plugin
