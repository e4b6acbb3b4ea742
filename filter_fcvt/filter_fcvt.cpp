#include "filter_fcvt.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "errors.h"
#include "mesh_convert.h"

namespace {

// Upper end of the default vertexCount: the paper's typical output size (Table 1), and a run
// of a few seconds on two cores; inputs with fewer vertices default to their own count.
constexpr int kDefaultMaxVertices = 5000;
constexpr int kMinVertices = 4;

int defaultVertexCount(const MeshModel* m)
{
    const int vn = m != nullptr ? m->cm.vn : kDefaultMaxVertices;
    return std::max(kMinVertices, std::min(vn, kDefaultMaxVertices));
}

// Log text for a figure; NaN (distance not computed) shown as "n/a".
QString num(double v, int precision = 4)
{
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QString("n/a");
}

}  // namespace

FilterFcvtPlugin::FilterFcvtPlugin()
{
    typeList << FP_FCVT_REMESH;
    for (FilterIDType tt : types())
        actionList << new QAction(filterName(tt), this);
}

QString FilterFcvtPlugin::pluginName() const
{
    return "FilterFCVT";
}

QString FilterFcvtPlugin::filterName(FilterIDType filter) const
{
    switch (filter) {
    case FP_FCVT_REMESH:
        // Frozen: the key of .mlx scripts.
        return "Remeshing: Field-Aligned CVT (FCVT)";
    default:
        return QString();
    }
}

QString FilterFcvtPlugin::filterInfo(FilterIDType filter) const
{
    switch (filter) {
    case FP_FCVT_REMESH:
        return "Isotropic remeshing by a Centroidal Voronoi Tessellation restricted to the surface, "
               "optionally aligned to a 6-RoSy direction field (lambda &gt; 0). The samples are "
               "optimised with L-BFGS on the exact restricted Voronoi diagram, and the output is its "
               "dual (the restricted Delaunay triangulation), placed in a new layer; the input layer "
               "is kept. Quality metrics (Q_min, Q_avg, angles, V6%, d_RMS, d_H) and per-stage "
               "times are written to the log.<br>"
               "See: <b>\"Field-Aligned Isotropic Surface Remeshing\"</b>, Computer Graphics "
               "Forum.";
    default:
        return QString();
    }
}

MeshFilterInterface::FilterClass FilterFcvtPlugin::getClass(QAction* a)
{
    switch (ID(a)) {
    case FP_FCVT_REMESH:
        return MeshFilterInterface::Remeshing;
    default:
        return MeshFilterInterface::Generic;
    }
}

MeshFilterInterface::FILTER_ARITY FilterFcvtPlugin::filterArity(QAction*) const
{
    return SINGLE_MESH;
}

int FilterFcvtPlugin::getRequirements(QAction*)
{
    return MeshModel::MM_NONE;
}

int FilterFcvtPlugin::getPreConditions(QAction*) const
{
    return MeshModel::MM_FACENUMBER;
}

int FilterFcvtPlugin::postCondition(QAction*) const
{
    // The input layer is not modified; the result is a new layer.
    return MeshModel::MM_NONE;
}

void FilterFcvtPlugin::initParameterSet(QAction* a, MeshModel& m, RichParameterList& par)
{
    addParameters(a, defaultVertexCount(&m), par);
}

void FilterFcvtPlugin::initParameterSet(QAction* a, MeshDocument& md, RichParameterList& par)
{
    addParameters(a, defaultVertexCount(md.mm()), par);
}

void FilterFcvtPlugin::addParameters(QAction* a, int vertexCountDefault, RichParameterList& par)
{
    switch (ID(a)) {
    case FP_FCVT_REMESH: {
        // Core defaults are the single source of truth for everything but vertexCount.
        const fieldcvt::RemeshParams defaults;
        par.addParam(RichInt(kVertexCount, vertexCountDefault, "Target vertices",
                             "Number of output vertices (Voronoi samples), at least 4. Default: "
                             "the input's vertex count, capped at 5000."));
        par.addParam(RichFloat(kLambda, float(defaults.lambda), "Field weight (lambda)",
                               "Weight of the field-alignment energy; 0 gives a pure isotropic "
                               "CVT."));
        par.addParam(RichInt(kCvtIterations, defaults.cvtIterations, "CVT iterations",
                             "L-BFGS iterations on the CVT energy (the paper uses 130)."));
        par.addParam(RichInt(kFcvtIterations, defaults.fcvtIterations, "FCVT iterations",
                             "L-BFGS iterations on CVT + lambda * field energy, run after the CVT "
                             "iterations."));
        par.addParam(RichInt(kSeed, int(defaults.seed), "Random seed",
                             "Seed of the initial sampling (>= 0); the same seed gives the same "
                             "output."));
        break;
    }
    default:
        break;
    }
}

bool FilterFcvtPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                                   vcg::CallBackPos* cb)
{
    // Nothing may escape into MeshLab: the GUI catches only std::bad_alloc and meshlabserver
    // nothing at all, so an exception would terminate the application.
    try {
        switch (ID(a)) {
        case FP_FCVT_REMESH: {
            const int vertexCount = par.getInt(kVertexCount);
            const double lambda = par.getFloat(kLambda);
            const int cvtIterations = par.getInt(kCvtIterations);
            const int fcvtIterations = par.getInt(kFcvtIterations);
            const int seed = par.getInt(kSeed);
            if (vertexCount < kMinVertices)
                return fail(QString("FCVT: vertexCount must be at least %1 (got %2)")
                                .arg(kMinVertices)
                                .arg(vertexCount));
            if (!(lambda >= 0) || !std::isfinite(lambda))
                return fail(QString("FCVT: lambda must be a finite number >= 0 (got %1)").arg(lambda));
            if (cvtIterations < 0)
                return fail(QString("FCVT: cvtIterations must be >= 0 (got %1)").arg(cvtIterations));
            if (fcvtIterations < 0)
                return fail(
                    QString("FCVT: fcvtIterations must be >= 0 (got %1)").arg(fcvtIterations));
            if (seed < 0)
                return fail(QString("FCVT: seed must be >= 0 (got %1)").arg(seed));

            fieldcvt::RemeshParams params;
            params.vertexCount = vertexCount;
            params.lambda = lambda;
            params.cvtIterations = cvtIterations;
            params.fcvtIterations = fcvtIterations;
            params.seed = static_cast<std::uint64_t>(seed);
            return remeshFcvt(md, params, cb);
        }
        default:
            return fail("FCVT: unknown filter");
        }
    } catch (const std::exception& e) {
        return fail(QString("FCVT: %1").arg(QString::fromUtf8(e.what())));
    } catch (...) {
        return fail("FCVT: unknown error");
    }
}

bool FilterFcvtPlugin::remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params,
                                  vcg::CallBackPos* cb)
{
    MeshModel* input = md.mm();
    if (input == nullptr)
        return fail("FCVT: no mesh loaded");
    if (input->cm.fn == 0)
        return fail(QString("FCVT: layer '%1' has no faces; a triangle mesh is required")
                        .arg(input->label()));

    const fieldcvt::TriMesh in = fcvt_plugin::toTriMesh(input->cm);

    // MeshLab's callback takes an int percent; the 2020.09 callbacks never ask to stop, so the
    // core is never cancelled from here. Calls are throttled to changes of percent or stage.
    int lastPercent = -1;
    std::string lastStage;
    fieldcvt::Progress progress = [cb, &lastPercent, &lastStage](const std::string& stage,
                                                            double percent) {
        if (cb == nullptr)
            return true;
        const int p = std::isfinite(percent) ? static_cast<int>(std::clamp(percent, 0.0, 100.0)) : 0;
        if (p != lastPercent || stage != lastStage) {
            lastPercent = p;
            lastStage = stage;
            cb(p, stage.c_str());
        }
        return true;
    };

    const fieldcvt::RemeshResult result = fieldcvt::remesh(in, params, progress);

    // The new layer is created only once the core succeeded, so a failure leaves the document
    // as it was; a failure while filling it removes it again.
    const QString layerName = input->label() + " FCVT";
    MeshModel* output = md.addNewMesh("", layerName, true);
    try {
        fcvt_plugin::fromTriMesh(result.mesh, output->cm);
        output->cm.Tr = input->cm.Tr;
        output->UpdateBoxAndNormals();
    } catch (...) {
        md.delMesh(output);
        md.setCurrentMesh(input->id());
        throw;
    }
    if (cb != nullptr)
        cb(100, "FCVT done");
    logReport(result, output->label());
    return true;
}

bool FilterFcvtPlugin::fail(const QString& message)
{
    errorMessage = message;
    Log(GLLogStream::WARNING, message.toStdString());
    return false;
}

void FilterFcvtPlugin::logReport(const fieldcvt::RemeshResult& r, const QString& layerName)
{
    const fieldcvt::QualityMetrics& m = r.metrics;
    Log(QString("FCVT: new layer '%1': %2 vertices, %3 faces, %4 energy evaluations")
            .arg(layerName)
            .arg(r.mesh.vertexCount())
            .arg(r.mesh.faceCount())
            .arg(r.evaluations)
            .toStdString());
    Log(QString("FCVT metrics: Q_min %1, Q_avg %2, theta_min %3 deg, mean theta_min %4 deg, "
                "theta_max %5 deg, %theta<30 %6, %theta>90 %7, V6% %8, d_RMS %9, d_H %10 "
                "(fractions of the input diagonal)")
            .arg(num(m.qMin))
            .arg(num(m.qAvg))
            .arg(num(m.thetaMin))
            .arg(num(m.thetaMinAvg))
            .arg(num(m.thetaMax))
            .arg(num(m.pctLt30))
            .arg(num(m.pctGt90))
            .arg(num(m.v6Pct))
            .arg(num(m.dRms))
            .arg(num(m.dH))
            .toStdString());
    QString times = "FCVT times:";
    for (const fieldcvt::StageTime& t : r.stageTimes)
        times += QString(" %1 %2 s,").arg(QString::fromStdString(t.stage)).arg(num(t.seconds, 3));
    times += QString(" total %1 s").arg(num(r.totalSeconds, 3));
    Log(times.toStdString());
    const auto topology = [](const fieldcvt::TopologySummary& t) {
        return QString("genus %1, %2 boundary loops, %3 components%4")
            .arg(t.genus)
            .arg(t.boundaryLoops)
            .arg(t.components)
            .arg(t.manifold() ? "" : ", NON-MANIFOLD");
    };
    Log(QString("FCVT topology: input %1; output %2")
            .arg(topology(r.inputTopology), topology(r.outputTopology))
            .toStdString());
    for (const std::string& w : r.warnings)
        Log(GLLogStream::WARNING, "FCVT warning: " + w);
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterFcvtPlugin)
