#include "fcvt_filters.h"

#include <vcg/complex/allocate.h>

#include <QApplication>
#include <QFileInfo>
#include <QPointer>
#include <QTimer>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <iterator>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "closest_point.h"
#include "errors.h"
#include "field_of_input.h"
#include "field.h"
#include "field_drawing.h"
#include "filter_run.h"
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

QString pluginName() { return "FilterFCVT"; }

QString filterName(FilterId filter)
{
    switch (filter) {
    case kRemesh:
        // Frozen: the key of .mlx scripts.
        return "Remeshing: Field-Aligned CVT (FCVT)";
    case kField: return "Compute 6-RoSy Field";
    case kQuality: return "Remeshing Quality Report (FCVT)";
    default: return QString();
    }
}

QString filterInfo(FilterId filter)
{
    switch (filter) {
    case kRemesh:
        // Kept to two lines: MeshLab shows it above the parameters, and Qt gives the dialog at
        // most 2/3 of the screen's height (682 pixels at 1280x1024), below which MeshLab 2020.09
        // clips the last row. What each parameter does is in its tooltip (the Help button).
        return "Isotropic remeshing into a new layer: a centroidal Voronoi tessellation with edges "
               "aligned to a 6-RoSy field, then valence optimisation (<b>\"Field-Aligned Isotropic "
               "Surface Remeshing\"</b>).";
    case kField:
        return "Computes a 6-way rotationally symmetric direction field on the current mesh: the "
               "extrinsically smooth field of Instant Meshes (Jakob et al. 2015), aligned to "
               "boundaries and sharp edges, or the maximal / minimal principal-curvature "
               "direction. Stores one representative direction per vertex as the per-vertex "
               "attribute <i>rosy</i> (vertices on no face get (0,0,0)), logs the number of "
               "singularities, and adds a layer \"6-RoSy field\" that draws the six directions as "
               "a cross of thin strips, lifted a little off the surface, at each vertex (at most "
               "'Crosses drawn' of them, on a uniform grid). The geometry of the current mesh is "
               "unchanged.";
    case kQuality:
        return "Writes the remeshing quality figures of the current mesh to the log, as in Table 2 "
               "of <b>\"Field-Aligned Isotropic Surface Remeshing\"</b>: Q_min and Q_avg (triangle "
               "quality 2&radic;3&middot;area / (half-perimeter &middot; longest edge), 1 for an "
               "equilateral triangle), the smallest angle, the mean smallest angle, the largest "
               "angle, the % of triangles with an angle below 30&deg; or above 90&deg;, V6% (interior "
               "vertices of valence 6), and the topology (genus, boundary loops, components). "
               "Given a reference layer other than the current one (e.g. the input of a remeshing), "
               "also d_RMS and d_H, the symmetric RMS and Hausdorff distances as fractions of the "
               "reference's bounding-box diagonal.<br>"
               "Optionally colours the vertices by valence: interior vertices of valence &lt; 6 blue, "
               "&gt; 6 pink, 6 white; vertices on an open boundary are judged against valence 4 "
               "(the target of the valence optimisation): &lt; 4 blue, &gt; 4 pink, 4 white. "
               "The geometry is unchanged.";
    default: return QString();
    }
}

FilterKind filterKind(FilterId filter)
{
    switch (filter) {
    case kRemesh: return FilterKind::Remeshing;
    case kField: return FilterKind::Normal;
    case kQuality:
    default: return FilterKind::MeasureAndVertexColouring;
    }
}

double typedValue(float value)
{
    if (!std::isfinite(value)) return value;
    char text[64];
    const std::to_chars_result written = std::to_chars(text, text + sizeof text, value);  // shortest round trip
    double typed = value;
    if (written.ec != std::errc() || std::from_chars(text, written.ptr, typed).ec != std::errc()) return value;
    return typed;
}

int preConditions(FilterId) { return MeshModel::MM_FACENUMBER; }

int postCondition(FilterId filter)
{
    // The input layer's geometry and standard data are not modified (the field filter only adds
    // the custom attribute `rosy`); results are new layers. The quality report may colour the
    // current layer's vertices.
    return filter == kQuality ? int(MeshModel::MM_VERTCOLOR) : int(MeshModel::MM_NONE);
}

std::vector<ParamDef> parameters(FilterId filter, const MeshModel* current)
{
    ParamList par;
    addParameters(filter, nullptr, current, par);
    return par.defs;
}

void applyFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log, Callback* cb)
{
    FilterRun run(log);
    switch (filter) {
    case kRemesh: run.applyRemesh(md, par, cb); break;
    case kField: run.applyField(md, par, cb); break;
    case kQuality: run.applyQuality(md, par, cb); break;
    default: throw FilterFailure("FCVT: unknown filter");
    }
}

QString unexpectedFailure(const std::exception* e)
{
    // Escaped: an exception's text may quote the input (a name, a token) and must not reach the
    // log as raw control characters.
    return e != nullptr ? QString("FCVT: %1").arg(QString::fromStdString(fieldcvt::escapeControlCharacters(e->what())))
                        : QString("FCVT: unknown error");
}

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
    if (reference != nullptr) {
        if (cb != nullptr) cb(20, "FCVT: measuring distances");
        const fieldcvt::TriMesh ref = fcvt_plugin::toTriMesh(reference->cm);
        distance = fieldcvt::computeDistance(measured, ref, distanceSamples(measured, ref));
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
    return true;
}

void FilterRun::logInfo(const QString& line) { log_.info(plainLogText(line)); }

void FilterRun::logWarning(const QString& line) { log_.warning(plainLogText(line)); }

}  // namespace fcvt_plugin
