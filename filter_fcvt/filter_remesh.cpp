// The remeshing filter, "Remeshing: Field-Aligned CVT (FCVT)": its parameters read, the layer's
// data beside the geometry (a user field, a density, a selection), the core's run, the new layer
// and the log in stage order.
#include "filter_run.h"

#include <vcg/complex/allocate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "filter_parameters.h"
#include "layer_data.h"
#include "layer_texture.h"
#include "mesh_convert.h"
#include "progress.h"

namespace fcvt_plugin {

bool FilterRun::applyRemesh(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb)
{
    int vertexCount = par.getInt(kVertexCount);
    const double lambda = par.getFloat(kLambda);
    const int cvtIterations = par.getInt(kCvtIterations);
    const int fcvtIterations = par.getInt(kFcvtIterations);
    const int fieldSource = par.getEnum(kFieldSource);
    const int seed = par.getInt(kSeed);
    const int sizeMode = par.getEnum(kSizeMode);
    const double targetLength = par.getAbsPerc(kTargetLength);
    if (sizeMode != kSizeByVertexCount && sizeMode != kSizeByTargetLength)
        return fail(QString("FCVT: %1 must be 0 (vertex count) or 1 (target edge length), got %2")
                        .arg(parameterName(kSizeMode))
                        .arg(sizeMode));
    const bool selectedOnly = boolParam(par, kSelectedOnly, false);
    if (sizeMode == kSizeByTargetLength) {
        MeshModel* input = currentTriangleLayer(md);
        if (input == nullptr) return false;
        // In double and scale-robust (a float cross product overflows from coordinates ~1e10);
        // the selected faces' area with selectedOnly.
        const fieldcvt::TriMesh whole = fcvt_plugin::toTriMesh(input->cm);
        double area = fieldcvt::surfaceArea(whole);
        if (selectedOnly) {
            const std::vector<char> selected = selectedFaces(*input);
            area = 0;
            for (int f = 0; f < whole.faceCount(); ++f) area += selected[size_t(f)] ? fieldcvt::faceArea(whole, f) : 0.0;
        }
        fieldcvt::VertexCountFromLength size;
        try {
            size = fieldcvt::vertexCountForLength(area, targetLength, parameterName(kTargetLength).toStdString());
        } catch (const fieldcvt::InvalidInputError& e) {
            return fail(QString("FCVT: %1").arg(QString::fromStdString(e.what())));
        }
        if (!size.warning.empty()) logWarning(QString("FCVT warning: %1").arg(QString::fromStdString(size.warning)));
        logInfo(QString("FCVT size: target edge length %1 on area %2 gives %3 vertices")
                    .arg(targetLength)
                    .arg(area)
                    .arg(size.vertexCount));
        vertexCount = size.vertexCount;
    }
    // A script may carry any integer as the enum value: MeshLab does not check the range.
    checkFieldSourceAndSeed(fieldSource, kAllFieldSources, seed);
    // Parameters added after the first release are read with their defaults when a script lacks
    // them: MeshLab's GUI runs a script with the script's own list (MainWindow::runFilterScript).
    const fieldcvt::RemeshParams defaults;
    const double featureAngle = floatParam(par, kFeatureAngle, defaults.featureAngleDegrees);

    // The preset first, as the CLI's --preset; the values below override it.
    const int preset = enumParam(par, kPreset, kDefaultPresetIndex);
    if (preset < 0 || preset >= kPresetCount)
        return fail(
            QString("FCVT: %1 must be 0 (fast), 1 (default) or 2 (quality), got %2").arg(parameterName(kPreset)).arg(preset));
    fieldcvt::RemeshParams params;
    fieldcvt::applyPreset(params, kPresets[preset]);
    params.vertexCount = vertexCount;
    params.lambda = lambda;
    // A dialog always has a value: the iterations at RemeshParams' defaults mean "as the preset
    // says" (the default preset: FCVT 40, fewer on a large run, RemeshParams::
    // largeRunFcvtIterations); any other value is used, FCVT at every size, as --fcvt-iterations is.
    if (cvtIterations != defaults.cvtIterations) params.cvtIterations = cvtIterations;
    if (fcvtIterations != defaults.fcvtIterations) params.fcvtIterations = params.largeRunFcvtIterations = fcvtIterations;
    params.fieldSource = kFieldSources[fieldSource].source;
    params.seed = static_cast<std::uint64_t>(seed);
    params.valenceOptimization = boolParam(par, kValenceOptimization, defaults.valenceOptimization);
    params.featureAngleDegrees = featureAngle;
    const int density = densityChoice(par);
    if (density < kDensityUniform || density > kDensityVertexQuality)
        return fail(QString("FCVT: %1 must be 0 (uniform), 1 (curvature) or 2 (vertex quality), got %2")
                        .arg(parameterName(kAdaptive))
                        .arg(density));
    const double gradation = floatParam(par, kGradation, defaults.gradation);
    params.gradation = gradation;  // checked even when unused (the core reads it with curvature only)
    if (density == kDensityCurvature) params.density = fieldcvt::DensitySource::Curvature;
    // The core's one range check, in the dialog's names.
    fieldcvt::ParameterNames names;
    names.vertexCount = parameterName(kVertexCount).toStdString();
    names.lambda = parameterName(kLambda).toStdString();
    names.cvtIterations = parameterName(kCvtIterations).toStdString();
    names.fcvtIterations = parameterName(kFcvtIterations).toStdString();
    names.featureAngle = parameterName(kFeatureAngle).toStdString();
    names.gradation = parameterName(kGradation).toStdString();
    try {
        fieldcvt::checkRemeshParams(params, names);
    } catch (const fieldcvt::InvalidInputError& e) {
        return fail(QString("FCVT: %1").arg(QString::fromStdString(e.what())));
    }
    RemeshInputs inputs;
    inputs.densityFromQuality = density == kDensityVertexQuality;
    inputs.featuresFromSelection = boolParam(par, kFeatureSelection, false);
    inputs.colorIrregular = boolParam(par, kColorIrregular, false);
    params.repair = boolParam(par, kRepair, defaults.repair);
    params.exactCount = boolParam(par, kExactCount, defaults.exactCount);
    inputs.selectedOnly = selectedOnly;
    return remeshFcvt(md, params, inputs, cb);
}

//! The layer's data beside the geometry that the run takes: the per-vertex field (fieldSource
//! 'user'), the per-vertex density (adaptive 'vertex quality'), the selection's border as
//! feature lines (featureSelection); fails on what is missing or invalid.
void FilterRun::readLayerInputs(MeshModel& input, const fieldcvt::TriMesh& in, const RemeshInputs& inputs,
                                fieldcvt::RemeshParams& run)
{
    if (run.fieldSource == fieldcvt::FieldSource::User) {
        // One vector per live vertex, in the order of toTriMesh.
        // Not const: vcg's handle has no const operator[].
        auto rosy = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(input.cm, kRosyAttribute);
        if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(input.cm, rosy))
            fail(QString("FCVT: %1 'per-vertex attribute rosy' needs the per-vertex "
                         "Point3 attribute '%2' on layer '%3', which has none (run 'Compute "
                         "6-RoSy Field' on it first)")
                     .arg(parameterName(kFieldSource))
                     .arg(kRosyAttribute)
                     .arg(input.label()));
        run.userDirections.clear();
        run.userDirections.reserve(in.vertices.size());
        for (auto vi = input.cm.vert.begin(); vi != input.cm.vert.end(); ++vi)
            if (!vi->IsD()) run.userDirections.push_back(toVec3(rosy[vi]));
    }
    if (inputs.densityFromQuality) {
        if (!input.hasDataMask(MeshModel::MM_VERTQUALITY))
            fail(QString("FCVT: %1 'vertex quality' needs per-vertex quality on layer '%2', "
                         "which has none (compute one first, e.g. with 'Discrete Curvatures' or "
                         "'Per Vertex Quality Function', then make it positive)")
                     .arg(parameterName(kAdaptive))
                     .arg(input.label()));
        run.density = fieldcvt::DensitySource::PerVertex;
        run.vertexDensity.clear();
        run.vertexDensity.reserve(in.vertices.size());
        int bad = 0;
        double firstBad = 0;
        for (const CVertexO& v : input.cm.vert) {
            if (v.IsD()) continue;
            const double q = double(v.cQ());
            if (!(q > 0) || !std::isfinite(q)) {
                if (bad++ == 0) firstBad = q;
            }
            run.vertexDensity.push_back(q);
        }
        if (bad > 0)
            fail(QString("FCVT: %1 'vertex quality' takes the density from the per-vertex "
                         "quality, which must be finite and above 0 at every vertex; %2 of %3 "
                         "vertices of '%4' are not (e.g. %5). Map it to positive values first "
                         "(e.g. 'Per Vertex Quality Function' with q = abs(q) + 0.1)")
                     .arg(parameterName(kAdaptive))
                     .arg(bad)
                     .arg(run.vertexDensity.size())
                     .arg(input.label())
                     .arg(firstBad));
    }
    if (inputs.featuresFromSelection) {
        std::vector<char> selected;
        selected.reserve(in.faces.size());
        int selectedCount = 0;
        for (const CFaceO& f : input.cm.face)
            if (!f.IsD()) {
                selected.push_back(f.IsS() ? 1 : 0);
                selectedCount += f.IsS() ? 1 : 0;
            }
        run.featureEdges = selectionBorder(in, selected);
        if (run.featureEdges.empty())
            logWarning(QString("FCVT: %1 is on but the selection of '%2' (%3 of %4 faces) has "
                               "no border inside the mesh: no feature edges from it")
                           .arg(parameterName(kFeatureSelection))
                           .arg(input.label())
                           .arg(selectedCount)
                           .arg(selected.size()));
        else
            logInfo(QString("FCVT features: %1 edges on the border of the %2 selected faces")
                        .arg(run.featureEdges.size())
                        .arg(selectedCount));
    }
}

bool FilterRun::remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, const RemeshInputs& inputs,
                           vcg::CallBackPos* cb)
{
    // The filter's own time inside MeshLab, from the layer to the new layer (issue 35 item 2:
    // at most 1.1 times the CLI's remeshing stages; bench/filter_vs_cli.py).
    const auto start = std::chrono::steady_clock::now();
    MeshModel* input = currentTriangleLayer(md);
    if (input == nullptr) return false;

    // The layer's own faces (not the file's triangulation) where the face selection is used.
    fieldcvt::TriMesh in = surfaceOf(*input, inputs.featuresFromSelection || inputs.selectedOnly);
    const std::vector<char> selected = inputs.selectedOnly ? selectedFaces(*input) : std::vector<char>{};
    fieldcvt::RemeshParams run = params;
    run.outputInFloat = sizeof(Scalarm) == sizeof(float);  // the new layer's coordinates
    readLayerInputs(*input, in, inputs, run);

    // MeshLab's callback takes an int percent; the 2020.09 callbacks never ask to stop, so the
    // core is never cancelled from here. Calls are throttled to changes of percent or stage.
    int lastPercent = -1;
    std::string lastStage;
    fieldcvt::Progress progress = [cb, &lastPercent, &lastStage](const std::string& stage, double percent) {
        if (cb == nullptr) return true;
        const int p = std::isfinite(percent) ? static_cast<int>(std::clamp(percent, 0.0, 100.0)) : 0;
        if (p != lastPercent || stage != lastStage) {
            lastPercent = p;
            lastStage = stage;
            // "FCVT: CVT iterations" in the status bar; MeshLab draws the percent beside it.
            const QByteArray label = stageLabel(stage).toUtf8();
            cb(p, label.constData());
        }
        return true;
    };

    fieldcvt::RegionRemeshResult region;
    if (inputs.selectedOnly)
        region = fieldcvt::remeshRegion(in, selected, run, fieldcvt::RegionParams{}, progress);
    else
        region.result = fieldcvt::remesh(in, run, progress);
    const fieldcvt::RemeshResult& result = region.result;

    // The new layer is created only once the core succeeded, so a failure leaves the document
    // as it was; a failure while filling it removes it again.
    const QString layerName = outputLayerName(input->label());
    MeshModel* output = md.addNewMesh("", layerName, true);
    std::vector<QString> outputLines;  // logged after the run's own lines, in stage order
    try {
        fcvt_plugin::fromTriMesh(result.mesh, output->cm);
        if (!result.outputDirections.empty()) {
            if (result.outputDirections.size() != size_t(output->cm.vn))
                throw fieldcvt::Error("the output field has " + std::to_string(result.outputDirections.size()) +
                                      " directions for " + std::to_string(output->cm.vn) + " vertices");
            auto rosy = pointAttribute(output->cm, kRosyAttribute);
            for (size_t i = 0; i < result.outputDirections.size(); ++i) rosy[i] = toPoint3m(result.outputDirections[i]);
        }
        output->cm.Tr = input->cm.Tr;
        updateBoxAndNormals(*output);
        KeptData keep;
        keep.colour = input->hasDataMask(MeshModel::MM_VERTCOLOR);
        keep.quality = input->hasDataMask(MeshModel::MM_VERTQUALITY);
        keep.normals = input->hasDataMask(MeshModel::MM_VERTNORMAL);
        // With a field, the core has the input's normals at the output vertices already (the
        // interpolated corner normals at each vertex's closest point, which the CLI writes): no
        // closest-point search over the input for them, which took 3 % of the filter's time.
        const bool coreNormals = keep.normals && (!inputs.selectedOnly || region.wholeMesh) &&
                                 result.outputNormals.size() == size_t(output->cm.vn) &&
                                 output->cm.vn == int(output->cm.vert.size());
        if (coreNormals) {
            for (size_t i = 0; i < result.outputNormals.size(); ++i) output->cm.vert[i].N() = toPoint3m(result.outputNormals[i]);
            keep.normals = false;
        }
        int mask = 0;
        if (keep.colour) mask |= MeshModel::MM_VERTCOLOR;
        if (keep.quality) mask |= MeshModel::MM_VERTQUALITY;
        if (mask != 0) output->updateDataMask(mask);
        // Vertex i of `in` is the i-th live vertex of the input layer (toTriMesh's order).
        std::vector<const CVertexO*> inVerts;
        inVerts.reserve(in.vertices.size());
        for (const CVertexO& v : input->cm.vert)
            if (!v.IsD()) inVerts.push_back(&v);
        if (inVerts.size() != in.vertices.size()) throw fieldcvt::Error("input vertex count changed during the filter");
        transferVertexData(in, inVerts, keep, output->cm);
        if (inputs.selectedOnly) keepRegionData(*input, region.vertexOrigin, region.faceOrigin, keep, *output);
        if (keep.colour || keep.quality)
            outputLines.push_back(QString("FCVT: per-vertex %1 of '%2' transferred to the output by closest point")
                                      .arg(keep.colour && keep.quality ? "colour and quality"
                                           : keep.colour               ? "colour"
                                                                       : "quality")
                                      .arg(input->label()));
        // After a selection-only run the kept faces keep their own coordinates.
        const QString textureLine = transferLayerTexture(
            *input, result.mesh, inputs.selectedOnly && !region.wholeMesh ? region.faceOrigin : std::vector<int>{},
            result.threads, *output);
        if (!textureLine.isEmpty()) outputLines.push_back(textureLine);
        if (inputs.colorIrregular)
            outputLines.push_back("FCVT valence colours on '" + output->label() +
                                  "': " + applyValenceColours(result.mesh, *output));
    } catch (...) {
        removeLayer(md, output);
        md.setCurrentMesh(input->id());
        throw;
    }
    if (cb != nullptr) cb(100, "FCVT done");
    logReport(result, run, output->label(), input->label());
    if (inputs.selectedOnly) logRegion(region);
    for (const QString& line : outputLines) logInfo(line);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    logInfo(QString("FCVT filter time: %1 s from the layer to the new layer (the core's stages %2 s, the layer's "
                    "conversions and data %3 s)")
                .arg(num(wall, 3))
                .arg(num(result.totalSeconds, 3))
                .arg(num(std::max(0.0, wall - result.totalSeconds), 3)));
    addRunFigures(result, wall);
    return true;
}

void FilterRun::addRunFigures(const fieldcvt::RemeshResult& r, double wallSeconds)
{
    // The top level of `fcvt remesh --report` (cli/command_remesh.cpp), its "time_s" object
    // flattened: time_s_<stage> (a stage run twice counts both times), time_s_total the filter's
    // whole time, from the layer to the new layer (the CLI's: from reading to writing).
    FilterOutput& out = output_;
    out.addInteger("vertices", r.mesh.vertexCount());
    out.addInteger("faces", r.mesh.faceCount());
    out.addReal("mean_edge_length", fieldcvt::meanEdgeLength(r.mesh));
    out.addInteger("evaluations", r.evaluations);
    out.addInteger("fcvt_iterations", r.fcvtIterations);
    out.addInteger("threads_used", r.threads);
    out.addInteger("optimisation_faces", r.optimisationFaces);
    std::vector<std::pair<std::string, double>> times;
    for (const fieldcvt::StageTime& t : r.stageTimes) {
        auto it = std::find_if(times.begin(), times.end(), [&](const auto& s) { return s.first == t.stage; });
        if (it == times.end())
            times.emplace_back(t.stage, t.seconds);
        else
            it->second += t.seconds;
    }
    for (const auto& [stage, seconds] : times) out.addReal("time_s_" + stage, seconds);
    out.addReal("time_s_total", wallSeconds);
    // How many warnings the run logged (the core's "FCVT warning: ..." lines, the CLI report's
    // "warnings", and the filter's own about the layer). A count, not the texts: pymeshlab's
    // dict takes numbers, booleans and MeshLab's vectors and matrices, and drops a QString or a
    // QStringList; the lines are in the log (pymeshlab.MeshSet(verbose=True) prints it).
    out.addInteger("warnings", warnings_.size());
}

std::vector<char> FilterRun::selectedFaces(const MeshModel& input)
{
    std::vector<char> selected = faceSelection(input.cm);
    if (std::none_of(selected.begin(), selected.end(), [](char s) { return s != 0; }))
        fail(QString("FCVT: %1 is on but layer '%2' has no selected face (select the faces to remesh first, e.g. "
                     "with the selection tool or Filters > Selection > Conditional Face Selection)")
                 .arg(parameterName(kSelectedOnly))
                 .arg(input.label()));
    return selected;
}

void FilterRun::logRegion(const fieldcvt::RegionRemeshResult& region)
{
    if (region.wholeMesh) {
        logInfo("FCVT region: every face was selected: the whole layer remeshed");
        return;
    }
    const auto isNew = [](int origin) { return origin < 0; };
    logInfo(QString("FCVT region: %1 piece(s) of the selection remeshed (%2 kept as they were), %3 new vertices, %4 new "
                    "faces (selected on the new layer), %5 border vertices kept; the metrics above are the new faces' "
                    "(away from the border: theta_min %6, Q_avg %7); worst border edge / target length %8")
                .arg(region.regions - region.keptRegions)
                .arg(region.keptRegions)
                .arg(std::count_if(region.vertexOrigin.begin(), region.vertexOrigin.end(), isNew))
                .arg(std::count_if(region.faceOrigin.begin(), region.faceOrigin.end(), isNew))
                .arg(region.borderVertices)
                .arg(num(region.interiorMetrics.thetaMin))
                .arg(num(region.interiorMetrics.qAvg))
                .arg(num(region.worstBorderRatio)));
}

void FilterRun::logReport(const fieldcvt::RemeshResult& r, const fieldcvt::RemeshParams& run, const QString& layerName,
                          const QString& inputName)
{
    // In the order the stages ran: input (repair), field, optimisation, valence, result, times.
    for (const std::string& n : r.notes) logInfo(QString::fromStdString("FCVT note: " + n));
    for (int i = 0; i < r.inputWarnings && i < static_cast<int>(r.warnings.size()); ++i)
        logWarning(QString::fromStdString("FCVT warning: " + r.warnings[size_t(i)]));
    logInfo(run.repair ? QString("FCVT repair: %1")
                             .arg(r.repair.notes.empty() && r.repair.information.empty() ? "nothing to repair" : "done")
                       : QString("FCVT repair: off (strict input check)"));
    if (r.outputDirections.empty())
        logInfo("FCVT field: none (lambda = 0 or no FCVT iterations)");
    else
        logInfo(QString("FCVT field: %1; on %2: %3; stored at the output vertices as the per-vertex attribute '%4'")
                    .arg(kFieldSources[fieldSourceIndex(run.fieldSource)].label)
                    .arg(QString::fromStdString(fieldcvt::fieldMeshDescription(r)))
                    .arg(singularitySummary(r.singularities, r.inputTopology))
                    .arg(kRosyAttribute));
    if (run.density == fieldcvt::DensitySource::Curvature)
        logInfo(QString("FCVT density: from curvature, gradation %1").arg(num(run.gradation)));
    else if (run.density == fieldcvt::DensitySource::PerVertex)
        logInfo(QString("FCVT density: from the per-vertex quality of '%1'").arg(inputName));
    // E_CVT and E_field at the end of each phase (the last record of each).
    QString energies;
    for (size_t i = 0; i < r.energyHistory.size(); ++i) {
        const fieldcvt::EnergyRecord& e = r.energyHistory[i];
        if (i + 1 < r.energyHistory.size() && r.energyHistory[i + 1].phase == e.phase) continue;
        energies += QString("%1%2 E_CVT %3, E_field %4")
                        .arg(energies.isEmpty() ? "" : "; ")
                        .arg(QString::fromStdString(e.phase))
                        .arg(num(e.cvt, 6))
                        .arg(num(e.field, 6));
    }
    if (!energies.isEmpty()) logInfo("FCVT energy at the end of each phase: " + energies);
    if (run.valenceOptimization) {
        const fieldcvt::ValenceStats& v = r.valence;
        logInfo(QString("FCVT valence optimisation: V6% %1 before, %2 after; %3 flips, %4 collapses, %5 splits in %6 rounds")
                    .arg(num(v.v6Before))
                    .arg(num(v.v6After))
                    .arg(v.flips)
                    .arg(v.collapses)
                    .arg(v.splits)
                    .arg(v.rounds));
    } else {
        logInfo("FCVT valence optimisation: off");
    }
    for (size_t i = size_t(std::max(0, r.inputWarnings)); i < r.warnings.size(); ++i)
        logWarning(QString::fromStdString("FCVT warning: " + r.warnings[i]));
    const fieldcvt::QualityMetrics& m = r.metrics;
    logInfo(QString("FCVT: new layer '%1': %2 vertices, %3 faces, %4 energy evaluations")
                .arg(layerName)
                .arg(r.mesh.vertexCount())
                .arg(r.mesh.faceCount())
                .arg(r.evaluations));
    // The boundary figures only where there is a boundary (a closed output has none to measure).
    const QString boundary = r.outputTopology.boundaryLoops > 0 || r.inputTopology.boundaryLoops > 0
                                 ? QString(", d_boundary %1 (of the input diagonal), boundary vertices of valence 4: %2%")
                                       .arg(num(m.dBoundary))
                                       .arg(num(m.boundaryV4Pct))
                                 : QString();
    // The distances' sampling is said: the quality report filter samples more densely.
    const QString samples = run.distanceSamples > 0 ? QString("%1 random points per mesh").arg(run.distanceSamples)
                                                    : QString("20 random points per face");
    logInfo(QString("FCVT metrics: %1, d_RMS %2, d_H %3 (fractions of the input diagonal; %4, with every vertex and "
                    "face centroid)%5")
                .arg(qualityText(m))
                .arg(num(m.dRms))
                .arg(num(m.dH))
                .arg(samples)
                .arg(boundary));
    logInfo(QString("FCVT topology: input %1; output %2").arg(topologyText(r.inputTopology), topologyText(r.outputTopology)));
    logInfo(QString("FCVT size: mean edge length %1 (%2 vertices)").arg(num(meanEdgeLength(r.mesh))).arg(r.mesh.vertexCount()));
    QString times = QString("FCVT times (%1 thread%2):").arg(r.threads).arg(r.threads == 1 ? "" : "s");
    for (const fieldcvt::StageTime& t : r.stageTimes)
        times += QString(" %1 %2 s,").arg(QString::fromStdString(t.stage)).arg(num(t.seconds, 3));
    times += QString(" total %1 s").arg(num(r.totalSeconds, 3));
    logInfo(times);
}

}  // namespace fcvt_plugin
