#include "log_text.h"

#include <cmath>
#include <cstring>
#include <map>

#include "progress.h"

namespace fcvt_plugin {

QString plainLogText(const QString& text)
{
    QString out = text;
    out.replace(QChar('<'), QChar(0x2039));
    return out;
}

QString num(double v, int precision) { return std::isfinite(v) ? QString::number(v, 'g', precision) : QString("n/a"); }

namespace {

struct ParameterLabel {
    const char* key;
    const char* label;
};
// The keys are the filters' parameter names (FilterFcvtPlugin::k*), frozen .mlx API.
constexpr ParameterLabel kParameterLabels[] = {
    {"vertexCount", "Target vertices"},
    {"sizeMode", "Size by"},
    {"targetLength", "Target edge length"},
    {"adaptive", "Vertex density"},
    {"gradation", "Curvature gradation"},
    {"featureAngle", "Feature angle (deg)"},
    {"featureSelection", "Features from selection"},
    {"valenceOptimization", "Valence optimisation"},
    {"colorIrregular", "Colour irregular vertices"},
    {"lambda", "Field weight (lambda)"},
    {"fieldSource", "Field source"},
    {"cvtIterations", "CVT iterations"},
    {"fcvtIterations", "FCVT iterations"},
    {"seed", "Random seed"},
    {"repair", "Repair the input"},
    {"referenceLayer", "Reference layer (distances)"},
    {"maxCrosses", "Crosses drawn (at most)"},
    {"selectedOnly", "Remesh only selected faces"},
    {"exactCount", "Exact vertex count"},
    {"preset", "Preset"},
};

}  // namespace

QString parameterLabel(const char* key)
{
    for (const ParameterLabel& p : kParameterLabels)
        if (std::strcmp(p.key, key) == 0) return p.label;
    return key;
}

QString parameterName(const char* key) { return QString("'%1' (%2)").arg(parameterLabel(key), key); }

QString singularitySummary(const std::vector<fieldcvt::Singularity>& singularities, const fieldcvt::TopologySummary& topology)
{
    long long sum = 0;
    for (const fieldcvt::Singularity& s : singularities) sum += s.index;
    const long long chi = static_cast<long long>(topology.vertices) - topology.edges + topology.faces;
    const QString why =
        topology.boundaryLoops == 0
            ? QString("on a closed surface it is 6 x the Euler characteristic, here 6 x %1 = %2").arg(chi).arg(6 * chi)
            : QString("with %1 boundary loops it need not be 6 x the Euler characteristic (6 x %2 = %3)")
                  .arg(topology.boundaryLoops)
                  .arg(chi)
                  .arg(6 * chi);
    return QString("%1 singularities, index sum %2 (indices in sixths of a turn; %3)")
        .arg(singularities.size())
        .arg(sum)
        .arg(why);
}

QString stageLabel(const std::string& stage)
{
    static const std::map<std::string, const char*> labels = {
        {"prepare", "checking the input"},
        {"field", "computing the 6-RoSy field"},
        {"sampling", "sampling"},
        {"lloyd", "Lloyd warm-up"},
        {"cvt", "CVT iterations"},
        {"boundary", "placing samples on the boundary"},
        {"features", "placing samples on feature lines"},
        {"fcvt", "FCVT iterations"},
        {"rdt", "extracting the mesh"},
        {"valence", "valence optimisation"},
        {"metrics", "measuring quality"},
        {"done", "done"},
    };
    // "cvt 12/65": the stage's label, then its step.
    const std::string key = fieldcvt::stageName(stage);
    const QString step = QString::fromStdString(stage.substr(key.size()));
    const auto it = labels.find(key);
    return QString("FCVT: ") + (it != labels.end() ? QString(it->second) : QString::fromStdString(key)) + step;
}

QString qualityText(const fieldcvt::QualityMetrics& m)
{
    return QString(
               "Q_min %1, Q_avg %2, theta_min %3 deg, mean theta_min %4 deg, theta_max %5 deg, "
               "triangles with an angle under 30 deg %6%, over 90 deg %7%, V6% %8")
        .arg(num(m.qMin))
        .arg(num(m.qAvg))
        .arg(num(m.thetaMin))
        .arg(num(m.thetaMinAvg))
        .arg(num(m.thetaMax))
        .arg(num(m.pctLt30))
        .arg(num(m.pctGt90))
        .arg(num(m.v6Pct));
}

QString topologyText(const fieldcvt::TopologySummary& t)
{
    return QString("genus %1, %2 boundary loops, %3 components%4")
        .arg(t.genus)
        .arg(t.boundaryLoops)
        .arg(t.components)
        .arg(t.manifold() ? "" : ", NON-MANIFOLD");
}

QStringList fieldIgnoredText(const fieldcvt::InputReport& r)
{
    QStringList parts;
    if (r.removedUnreferencedVertices > 0)
        parts << QString("%1 vertices on no face (their rosy is (0,0,0))").arg(r.removedUnreferencedVertices);
    if (r.removedDegenerateFaces > 0) parts << QString("%1 degenerate (zero-area) faces").arg(r.removedDegenerateFaces);
    if (r.removedDuplicateFaces > 0) parts << QString("%1 duplicate faces").arg(r.removedDuplicateFaces);
    if (r.mergedDuplicateVertices > 0)
        parts << QString(
                     "%1 duplicate vertices (same coordinates) taken as one with the vertex they "
                     "repeat")
                     .arg(r.mergedDuplicateVertices);
    if (r.flippedFaces > 0)
        parts << QString(
                     "the orientation of %1 faces, read reversed to orient each component "
                     "consistently")
                     .arg(r.flippedFaces);
    if (r.splitNonManifoldVertices > 0)
        parts << QString("the connectivity at %1 non-manifold vertices, read as one vertex per fan of faces")
                     .arg(r.splitNonManifoldVertices);
    return parts;
}

QString valenceColourText(const ValenceColouring& c)
{
    return QString(
               "interior vertices: %1 of valence under 6 (blue), %2 of valence 6 (white), %3 over 6 "
               "(pink); boundary vertices (target 4): %4 under 4 (blue), %5 at 4 (white), %6 over 4 "
               "(pink)%7")
        .arg(c.interiorLow)
        .arg(c.interiorRegular)
        .arg(c.interiorHigh)
        .arg(c.boundaryLow)
        .arg(c.boundaryRegular)
        .arg(c.boundaryHigh)
        .arg(c.unused > 0 ? QString("; %1 vertices on no face (grey)").arg(c.unused) : QString());
}

}  // namespace fcvt_plugin
