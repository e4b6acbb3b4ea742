#include "fcvt_filters.h"

#include <common/GLLogStream.h>
#include <vcg/complex/allocate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "closest_point.h"
#include "errors.h"
#include "field.h"
#include "field_drawing.h"
#include "mesh_check.h"
#include "mesh_convert.h"
#include "metrics.h"
#include "progress.h"
#include "remesh.h"
#include "valence_colour.h"

namespace fcvt_plugin {

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

// Bounding-box diagonal of the layer (1 without a mesh): the range of targetLength.
float bboxDiagonal(const MeshModel* m)
{
    const float d = m != nullptr && !m->cm.bbox.IsNull() ? float(m->cm.bbox.Diag()) : 0.0f;
    return std::isfinite(d) && d > 0 ? d : 1.0f;
}

// The sizeMode enum (index = value in .mlx scripts, frozen).
enum SizeMode { kSizeByVertexCount = 0, kSizeByTargetLength = 1 };
const QStringList kSizeModeLabels = {"vertex count", "target edge length"};

// Above this a target edge length is taken for a mistake (hours of run time, gigabytes).
constexpr double kMaxVerticesFromLength = 5e6;

// Surface area of the live faces (coordinates as stored, like toTriMesh).
double surfaceArea(const CMeshO& cm)
{
    double area = 0;
    for (const CFaceO& f : cm.face) {
        if (f.IsD())
            continue;
        const Point3m e1 = f.cP(1) - f.cP(0);
        const Point3m e2 = f.cP(2) - f.cP(0);
        area += 0.5 * double((e1 ^ e2).Norm());
    }
    return area;
}

// Mean length over the distinct (undirected) edges of the faces.
double meanEdgeLength(const fieldcvt::TriMesh& mesh)
{
    std::vector<std::pair<int, int>> edges;
    edges.reserve(mesh.faces.size() * 3);
    for (const fieldcvt::Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    double sum = 0;
    for (const auto& e : edges)
        sum += (mesh.vertices[size_t(e.first)] - mesh.vertices[size_t(e.second)]).norm();
    return edges.empty() ? 0.0 : sum / double(edges.size());
}

// The fieldSource enum: index in the RichEnum (the value stored in .mlx scripts, frozen) ->
// core source. "Compute 6-RoSy Field" offers the first kComputedFieldSources entries.
struct FieldSourceChoice {
    fieldcvt::FieldSource source;
    const char* label;
};
constexpr FieldSourceChoice kFieldSources[] = {
    {fieldcvt::FieldSource::Extrinsic, "extrinsic 6-RoSy"},
    {fieldcvt::FieldSource::CurvatureMax, "max curvature"},
    {fieldcvt::FieldSource::CurvatureMin, "min curvature"},
    {fieldcvt::FieldSource::User, "per-vertex attribute rosy"},
};
constexpr int kAllFieldSources = int(std::size(kFieldSources));
constexpr int kComputedFieldSources = 3;

QStringList fieldSourceLabels(int count)
{
    QStringList labels;
    for (int i = 0; i < count; ++i)
        labels << kFieldSources[i].label;
    return labels;
}

int fieldSourceIndex(fieldcvt::FieldSource source)
{
    for (int i = 0; i < kAllFieldSources; ++i)
        if (kFieldSources[i].source == source)
            return i;
    return 0;
}

fieldcvt::Vec3 toVec3(const Point3m& p)
{
    return fieldcvt::Vec3(double(p[0]), double(p[1]), double(p[2]));
}

Point3m toPoint3m(const fieldcvt::Vec3& v)
{
    return Point3m(Scalarm(v.x()), Scalarm(v.y()), Scalarm(v.z()));
}

// A handle to the per-vertex Point3m attribute `name`, created if missing; an attribute of that
// name but another type is replaced (vcg asserts on adding a name that exists).
CMeshO::PerVertexAttributeHandle<Point3m> pointAttribute(CMeshO& cm, const char* name)
{
    auto h = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(cm, name);
    if (vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(cm, h))
        return h;
    vcg::tri::Allocator<CMeshO>::DeletePerVertexAttribute(cm, name);
    return vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<Point3m>(cm, name);
}

// Singularity count and index sum (in sixths of a turn; 6·χ on a closed surface).
QString singularitySummary(const std::vector<fieldcvt::Singularity>& singularities)
{
    long long sum = 0;
    for (const fieldcvt::Singularity& s : singularities)
        sum += s.index;
    return QString("%1 singularities (index sum %2/6)").arg(singularities.size()).arg(sum);
}

// Log text for a figure; NaN (distance not computed) shown as "n/a".
QString num(double v, int precision = 4)
{
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QString("n/a");
}

// The core's stage names as the status bar shows them.
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

// The Table 2 figures of computeQuality as one log line (distances apart).
QString qualityText(const fieldcvt::QualityMetrics& m)
{
    return QString("Q_min %1, Q_avg %2, theta_min %3 deg, mean theta_min %4 deg, theta_max %5 deg, "
                   "%theta<30 %6, %theta>90 %7, V6% %8")
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

// Distance samples per mesh: dense enough for a Hausdorff figure at the meshes' resolution,
// capped for big ones (the core's choice in remesh()).
int distanceSamples(const fieldcvt::TriMesh& a, const fieldcvt::TriMesh& b)
{
    return std::clamp(20 * (a.faceCount() + b.faceCount()), 20000, 200000);
}

// Writes the valence colours to the live vertices of `cm` (vertex i of `mesh` = i-th live vertex)
// and returns the counts as a log line.
QString applyValenceColours(const fieldcvt::TriMesh& mesh, MeshModel& layer)
{
    const fcvt_plugin::ValenceColouring c = fcvt_plugin::colourByValence(mesh);
    layer.updateDataMask(MeshModel::MM_VERTCOLOR);
    size_t i = 0;
    for (CVertexO& v : layer.cm.vert)
        if (!v.IsD() && i < c.colours.size())
            v.C() = c.colours[i++];
    if (i != c.colours.size())
        throw fieldcvt::Error("valence colours: vertex count mismatch");
    return QString("interior vertices: %1 of valence < 6 (blue), %2 = 6 (white), %3 > 6 (pink); "
                   "boundary vertices (target 4): %4 < 4 (blue), %5 = 4 (white), %6 > 4 (pink)%7")
        .arg(c.interiorLow)
        .arg(c.interiorRegular)
        .arg(c.interiorHigh)
        .arg(c.boundaryLow)
        .arg(c.boundaryRegular)
        .arg(c.boundaryHigh)
        .arg(c.unused > 0 ? QString("; %1 vertices on no face (grey)").arg(c.unused) : QString());
}

// Feature lines from a face selection: the edges between a selected and an unselected face
// (vertex indices of `mesh`, whose face i is the i-th live face, `selected[i]` its flag).
std::vector<std::array<int, 2>> selectionBorder(const fieldcvt::TriMesh& mesh,
                                                const std::vector<char>& selected)
{
    std::map<std::pair<int, int>, std::pair<int, int>> edges;  // edge -> (faces, selected faces)
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
            auto& count = edges[{std::min(a, b), std::max(a, b)}];
            ++count.first;
            count.second += selected[f] ? 1 : 0;
        }
    std::vector<std::array<int, 2>> border;
    for (const auto& [edge, count] : edges)
        if (count.second > 0 && count.second < count.first)
            border.push_back({edge.first, edge.second});
    return border;
}

// What the output keeps of the input's per-vertex data.
struct KeptData {
    bool colour = false, quality = false, normals = false;
    bool any() const { return colour || quality || normals; }
};

// Per-vertex colour / quality / normal of the input carried to the output: for each output
// vertex the closest point on the input (`in`, whose vertex i is `inVerts[i]`) and barycentric
// interpolation of its face's three corners. Normals are renormalised (a degenerate result keeps
// the output's own normal).
void transferVertexData(const fieldcvt::TriMesh& in, const std::vector<const CVertexO*>& inVerts,
                        const KeptData& keep, CMeshO& out)
{
    if (!keep.any() || in.faces.empty())
        return;
    const fieldcvt::ClosestPointTree tree(in);
    for (CVertexO& v : out.vert) {
        if (v.IsD())
            continue;
        const fieldcvt::ClosestPoint cp = tree.closest(toVec3(v.cP()));
        if (cp.face < 0)
            continue;
        const fieldcvt::Face& f = in.faces[size_t(cp.face)];
        const CVertexO* c[3] = {inVerts[size_t(f[0])], inVerts[size_t(f[1])], inVerts[size_t(f[2])]};
        const double w[3] = {cp.barycentric.x(), cp.barycentric.y(), cp.barycentric.z()};
        if (keep.colour) {
            for (int ch = 0; ch < 4; ++ch) {
                double x = 0;
                for (int k = 0; k < 3; ++k)
                    x += w[k] * double(c[k]->cC()[ch]);
                v.C()[ch] = static_cast<unsigned char>(std::clamp(std::lround(x), 0L, 255L));
            }
        }
        if (keep.quality) {
            double q = 0;
            for (int k = 0; k < 3; ++k)
                q += w[k] * double(c[k]->cQ());
            v.Q() = static_cast<float>(q);
        }
        if (keep.normals) {
            fieldcvt::Vec3 n(0, 0, 0);
            for (int k = 0; k < 3; ++k)
                n += w[k] * toVec3(c[k]->cN());
            const double len = n.norm();
            if (std::isfinite(len) && len > 1e-12)
                v.N() = toPoint3m(n / len);
        }
    }
}

// The parameter declarations below read like both MeshLabs' own (par.addParam(RichInt(...)));
// these build the neutral ParamDef the glue turns into its MeshLab's Rich* parameters.
struct ParamList {
    std::vector<ParamDef> defs;
    void addParam(ParamDef p) { defs.push_back(std::move(p)); }
};

ParamDef makeParam(ParamDef::Type type, const char* name, double value, const QString& label,
                   const QString& tooltip)
{
    ParamDef p;
    p.type = type;
    p.name = name;
    p.value = value;
    p.label = label;
    p.tooltip = tooltip;
    return p;
}
ParamDef RichInt(const char* name, int value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Int, name, value, label, tooltip);
}
ParamDef RichFloat(const char* name, float value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Float, name, double(value), label, tooltip);
}
ParamDef RichBool(const char* name, bool value, const QString& label, const QString& tooltip)
{
    return makeParam(ParamDef::Bool, name, value ? 1 : 0, label, tooltip);
}
ParamDef RichEnum(const char* name, int value, const QStringList& labels, const QString& label,
                  const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::Enum, name, value, label, tooltip);
    p.enumLabels = labels;
    return p;
}
ParamDef RichAbsPerc(const char* name, float value, float min, float max, const QString& label,
                     const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::AbsPerc, name, double(value), label, tooltip);
    p.min = double(min);
    p.max = double(max);
    return p;
}
ParamDef RichMesh(const char* name, const MeshModel*, const MeshDocument*, const QString& label,
                  const QString& tooltip)
{
    return makeParam(ParamDef::Mesh, name, 0, label, tooltip);
}

//! One filter run: the typed bodies of the three filters, with the plugin's log.
class FilterRun {
public:
    explicit FilterRun(FilterLog& log) : log_(log) {}

    bool applyRemesh(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);
    bool applyField(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);
    bool applyQuality(MeshDocument& md, const ParamValues& par, vcg::CallBackPos* cb);

private:
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
    //! Fails the filter: throws FilterFailure(message), which the glue reports.
    [[noreturn]] bool fail(const QString& message) { throw FilterFailure(message); }
    //! The current layer if it holds faces; otherwise fails.
    MeshModel* currentTriangleLayer(MeshDocument& md);
    void logReport(const fieldcvt::RemeshResult& result, const QString& layerName);

    void Log(const std::string& text) { log_.info(QString::fromStdString(text)); }
    void Log(GLLogStream::Levels level, const std::string& text)
    {
        if (level == GLLogStream::WARNING)
            log_.warning(QString::fromStdString(text));
        else
            log_.info(QString::fromStdString(text));
    }

    FilterLog& log_;
};

void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par);

}  // namespace

QString pluginName()
{
    return "FilterFCVT";
}

QString filterName(FilterId filter)
{
    switch (filter) {
    case kRemesh:
        // Frozen: the key of .mlx scripts.
        return "Remeshing: Field-Aligned CVT (FCVT)";
    case kField:
        return "Compute 6-RoSy Field";
    case kQuality:
        return "Remeshing Quality Report (FCVT)";
    default:
        return QString();
    }
}

QString filterInfo(FilterId filter)
{
    switch (filter) {
    case kRemesh:
        return "Isotropic remeshing by a Centroidal Voronoi Tessellation restricted to the surface, "
               "optionally aligned to a 6-RoSy direction field (lambda &gt; 0). The samples are "
               "optimised with L-BFGS on the exact restricted Voronoi diagram, and the output is its "
               "dual (the restricted Delaunay triangulation), placed in a new layer; the input layer "
               "is kept. Quality metrics (Q_min, Q_avg, angles, V6%, d_RMS, d_H) and per-stage "
               "times are written to the log.<br>"
               "See: <b>\"Field-Aligned Isotropic Surface Remeshing\"</b>, Computer Graphics "
               "Forum.<br>"
               "The field that the edges follow (fieldSource) is an extrinsically smooth 6-RoSy "
               "field, a principal-curvature direction, or the per-vertex attribute <i>rosy</i> of "
               "the input (e.g. from <i>Compute 6-RoSy Field</i>). The output layer carries the "
               "field interpolated at its vertices as the per-vertex attribute <i>rosy</i>.<br>"
               "Input repair (<i>repair</i>, on by default; every step counted in the log): "
               "vertices at the same coordinates, and border vertices closer than 0.001 of the "
               "mean edge length (cracks, seams, T-junctions), are welded, never farther apart; "
               "duplicate and opposite duplicate faces are removed; non-manifold edges are split "
               "into manifold sheets, non-manifold vertices into one vertex per fan; a "
               "non-orientable piece is cut along a seam into orientable ones; components that "
               "would get fewer than 8 samples and hold under 1% of the area are dropped (if none "
               "is left the filter fails and says how many vertices are needed). Refused even "
               "so: no faces, NaN/Inf coordinates, bad indices. With <i>repair</i> off, "
               "non-manifold edges and non-orientable components are refused as before and every "
               "component is kept.";
    case kField:
        return "Computes a 6-way rotationally symmetric direction field on the current mesh: the "
               "extrinsically smooth field of Instant Meshes (Jakob et al. 2015), aligned to "
               "boundaries and sharp edges, or the maximal / minimal principal-curvature "
               "direction. Stores one representative direction per vertex as the per-vertex "
               "attribute <i>rosy</i> (vertices dropped by the input check get (0,0,0)), logs the "
               "number of singularities, and adds a layer \"6-RoSy field\" that draws the six "
               "directions at each vertex (a uniform subset on meshes over 20000 vertices) as "
               "line segments. The geometry of the current mesh is unchanged.";
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
    default:
        return QString();
    }
}

FilterKind filterKind(FilterId filter)
{
    switch (filter) {
    case kRemesh:
        return FilterKind::Remeshing;
    case kField:
        return FilterKind::Normal;
    case kQuality:
    default:
        return FilterKind::MeasureAndVertexColouring;
    }
}

int preConditions(FilterId)
{
    return MeshModel::MM_FACENUMBER;
}

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

void applyFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log,
                 Callback* cb)
{
    FilterRun run(log);
    switch (filter) {
    case kRemesh:
        run.applyRemesh(md, par, cb);
        break;
    case kField:
        run.applyField(md, par, cb);
        break;
    case kQuality:
        run.applyQuality(md, par, cb);
        break;
    default:
        throw FilterFailure("FCVT: unknown filter");
    }
}

QString unexpectedFailure(const std::exception* e)
{
    return e != nullptr ? QString("FCVT: %1").arg(QString::fromUtf8(e->what())) : QString("FCVT: unknown error");
}

namespace {

void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par)
{
    const int vertexCountDefault = defaultVertexCount(m);
    const float diagonal = bboxDiagonal(m);
    switch (a) {
    case kRemesh: {
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
        par.addParam(RichEnum(kFieldSource, fieldSourceIndex(defaults.fieldSource),
                              fieldSourceLabels(kAllFieldSources), "Field source",
                              "The 6-RoSy field the edges are aligned to: the extrinsically smooth "
                              "field, the max or min principal-curvature direction, or the "
                              "per-vertex Point3 attribute 'rosy' of the input layer."));
        par.addParam(RichInt(kSeed, int(defaults.seed), "Random seed",
                             "Seed of the initial sampling (>= 0); the same seed gives the same "
                             "output."));
        par.addParam(RichEnum(kSizeMode, kSizeByVertexCount, kSizeModeLabels, "Size by",
                              "How the output size is given: by the number of vertices (Target "
                              "vertices) or by the edge length (Target edge length), converted to "
                              "a vertex count through the surface area."));
        par.addParam(RichAbsPerc(kTargetLength, 0.01f * diagonal, 0.0f, diagonal,
                                 "Target edge length",
                                 "Wanted edge length in world units (used when Size by is 'target "
                                 "edge length'); the vertex count is about 2 * area / (sqrt(3) * "
                                 "length^2). Default: 1% of the bounding-box diagonal."));
        // Added after the first release: appended, so older scripts keep their order.
        par.addParam(RichBool(kValenceOptimization, defaults.valenceOptimization,
                              "Valence optimisation",
                              "After the extraction, edge flips, collapses and splits that bring "
                              "vertices to valence 6 (4 on boundaries), then a relaxation that "
                              "realigns the edges (paper section 4.4)."));
        par.addParam(RichFloat(kFeatureAngle, float(defaults.featureAngleDegrees),
                               "Feature angle (deg)",
                               "Input edges whose faces meet at a dihedral angle of at least this "
                               "many degrees are sharp features that the output follows; 0 = no "
                               "sharp features (0..180)."));
        par.addParam(RichBool(kFeatureSelection, false, "Features from selection",
                              "Also treat the border of the input's face selection (edges between a "
                              "selected and an unselected face) as feature lines."));
        par.addParam(RichBool(kAdaptive, false, "Adaptive (density from vertex quality)",
                              "Sample density from the input's per-vertex quality (every value "
                              "must be finite and > 0): more vertices where the quality is "
                              "higher, the vertex count unchanged. Off: uniform density."));
        par.addParam(RichBool(kColorIrregular, false, "Colour irregular vertices",
                              "Colour the output's vertices by valence: blue below 6 (4 on a "
                              "boundary), pink above, white at it. Replaces the colour carried "
                              "over from the input."));
        // Appended (issue 17), so older scripts keep their order.
        par.addParam(RichBool(kRepair, defaults.repair, "Repair the input",
                              "Before remeshing, weld coincident and nearly coincident border "
                              "vertices (cracks, seams, T-junctions), remove duplicate and opposite "
                              "faces, split non-manifold edges and vertices, cut non-orientable "
                              "pieces along a seam, and drop components too small for the vertex "
                              "count; each step is counted in the log. Off: the strict check only, "
                              "which refuses non-manifold edges and non-orientable pieces."));
        break;
    }
    case kField: {
        const fieldcvt::FieldParams defaults;
        par.addParam(RichEnum(kFieldSource, fieldSourceIndex(defaults.source),
                              fieldSourceLabels(kComputedFieldSources), "Field source",
                              "The extrinsically smooth 6-RoSy field (aligned to boundaries and "
                              "sharp edges), or the max or min principal-curvature direction."));
        par.addParam(RichInt(kSeed, int(defaults.seed), "Random seed",
                             "Seed of the random initial directions of the smooth field (>= 0); "
                             "the same seed gives the same field."));
        break;
    }
    case kQuality: {
        // The default reference is the measured layer itself, which means "no distances".
        const char* description = "Reference layer (distances)";
        const char* tooltip = "The layer d_RMS and d_H are measured against (e.g. the input of the "
                              "remeshing). The current layer itself: no distances.";
        if (md != nullptr && m != nullptr)
            par.addParam(RichMesh(kReferenceLayer, m, md, description, tooltip));
        else  // no document: a parameter without a mesh (only for completeness of the overload)
            par.addParam(RichMesh(kReferenceLayer, static_cast<MeshModel*>(nullptr), nullptr,
                                  description, tooltip));
        par.addParam(RichBool(kColorIrregular, true, "Colour irregular vertices",
                              "Colour the vertices by valence: blue below 6 (4 on a boundary), "
                              "pink above, white at it."));
        break;
    }
    default:
        break;
    }
}

bool FilterRun::applyRemesh(MeshDocument& md, const ParamValues& par,
                                   vcg::CallBackPos* cb)
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
        return fail(QString("FCVT: sizeMode must be 0..1 (got %1)").arg(sizeMode));
    if (sizeMode == kSizeByTargetLength) {
        MeshModel* input = currentTriangleLayer(md);
        if (input == nullptr)
            return false;
        if (!(targetLength > 0) || !std::isfinite(targetLength))
            return fail(QString("FCVT: targetLength must be a number > 0 (got %1)").arg(targetLength));
        const double area = surfaceArea(input->cm);
        // Equilateral triangulation of edge L: about 2 faces per vertex of area sqrt(3) L^2 / 4.
        const double wanted = 2.0 * area / (std::sqrt(3.0) * targetLength * targetLength);
        if (!std::isfinite(wanted) || wanted > kMaxVerticesFromLength)
            return fail(QString("FCVT: targetLength %1 on a surface of area %2 would give %3 "
                                "vertices, more than the maximum %4; choose a longer edge")
                            .arg(targetLength)
                            .arg(area)
                            .arg(wanted, 0, 'g', 4)
                            .arg(kMaxVerticesFromLength, 0, 'g', 4));
        const int fromLength = std::max(kMinVertices, int(std::lround(wanted)));
        Log(QString("FCVT size: target edge length %1 on area %2 -> %3 vertices")
                .arg(targetLength)
                .arg(area)
                .arg(fromLength)
                .toStdString());
        vertexCount = fromLength;
    }
    if (vertexCount < kMinVertices)
        return fail(QString("FCVT: vertexCount must be at least %1 (got %2)")
                        .arg(kMinVertices)
                        .arg(vertexCount));
    if (!(lambda >= 0) || !std::isfinite(lambda))
        return fail(QString("FCVT: lambda must be a finite number >= 0 (got %1)").arg(lambda));
    if (cvtIterations < 0)
        return fail(QString("FCVT: cvtIterations must be >= 0 (got %1)").arg(cvtIterations));
    if (fcvtIterations < 0)
        return fail(QString("FCVT: fcvtIterations must be >= 0 (got %1)").arg(fcvtIterations));
    // A script may carry any integer as the enum value: MeshLab does not check the range.
    if (fieldSource < 0 || fieldSource >= kAllFieldSources)
        return fail(QString("FCVT: fieldSource must be 0..%1 (got %2)")
                        .arg(kAllFieldSources - 1)
                        .arg(fieldSource));
    if (seed < 0)
        return fail(QString("FCVT: seed must be >= 0 (got %1)").arg(seed));
    const double featureAngle = par.getFloat(kFeatureAngle);
    if (!(featureAngle >= 0 && featureAngle <= 180))
        return fail(QString("FCVT: featureAngle must be 0..180 degrees, 0 = off (got %1)").arg(featureAngle));

    fieldcvt::RemeshParams params;
    params.vertexCount = vertexCount;
    params.lambda = lambda;
    params.cvtIterations = cvtIterations;
    params.fcvtIterations = fcvtIterations;
    params.fieldSource = kFieldSources[fieldSource].source;
    params.seed = static_cast<std::uint64_t>(seed);
    params.valenceOptimization = par.getBool(kValenceOptimization);
    params.featureAngleDegrees = featureAngle;
    RemeshInputs inputs;
    inputs.densityFromQuality = par.getBool(kAdaptive);
    inputs.featuresFromSelection = par.getBool(kFeatureSelection);
    inputs.colorIrregular = par.getBool(kColorIrregular);
    params.repair = par.getBool(kRepair);
    return remeshFcvt(md, params, inputs, cb);
}

bool FilterRun::applyQuality(MeshDocument& md, const ParamValues& par,
                                    vcg::CallBackPos* cb)
{
    MeshModel* mesh = currentTriangleLayer(md);
    if (mesh == nullptr)
        return false;
    MeshModel* reference = par.getMesh(kReferenceLayer);
    return qualityReport(*mesh, reference == mesh ? nullptr : reference, par.getBool(kColorIrregular), cb);
}

bool FilterRun::applyField(MeshDocument& md, const ParamValues& par,
                                  vcg::CallBackPos* cb)
{
    const int fieldSource = par.getEnum(kFieldSource);
    const int seed = par.getInt(kSeed);
    if (fieldSource < 0 || fieldSource >= kComputedFieldSources)
        return fail(QString("FCVT: fieldSource must be 0..%1 (got %2)")
                        .arg(kComputedFieldSources - 1)
                        .arg(fieldSource));
    if (seed < 0)
        return fail(QString("FCVT: seed must be >= 0 (got %1)").arg(seed));

    fieldcvt::FieldParams params;
    params.source = kFieldSources[fieldSource].source;
    params.seed = static_cast<std::uint64_t>(seed);
    return computeRosyField(md, params, cb);
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

bool FilterRun::remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params,
                                  const RemeshInputs& inputs, vcg::CallBackPos* cb)
{
    MeshModel* input = currentTriangleLayer(md);
    if (input == nullptr)
        return false;

    fieldcvt::TriMesh in = fcvt_plugin::toTriMesh(input->cm);
    fieldcvt::RemeshParams run = params;
    if (run.fieldSource == fieldcvt::FieldSource::User) {
        // One vector per live vertex, in the order of toTriMesh.
        // Not const: vcg's handle has no const operator[].
        auto rosy =
            vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(input->cm, kRosyAttribute);
        if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(input->cm, rosy))
            return fail(QString("FCVT: fieldSource 'per-vertex attribute rosy' needs the per-vertex "
                                "Point3 attribute '%1' on layer '%2', which has none (run 'Compute "
                                "6-RoSy Field' on it first)")
                            .arg(kRosyAttribute)
                            .arg(input->label()));
        run.userDirections.clear();
        run.userDirections.reserve(in.vertices.size());
        for (auto vi = input->cm.vert.begin(); vi != input->cm.vert.end(); ++vi)
            if (!vi->IsD())
                run.userDirections.push_back(toVec3(rosy[vi]));
    }
    if (inputs.densityFromQuality) {
        if (!input->hasDataMask(MeshModel::MM_VERTQUALITY))
            return fail(QString("FCVT: adaptive needs per-vertex quality on layer '%1', which has "
                                "none (compute one first, e.g. with 'Discrete Curvatures' or 'Per "
                                "Vertex Quality Function', then make it positive)")
                            .arg(input->label()));
        run.density = fieldcvt::DensitySource::PerVertex;
        run.vertexDensity.clear();
        run.vertexDensity.reserve(in.vertices.size());
        int bad = 0;
        double firstBad = 0;
        for (const CVertexO& v : input->cm.vert) {
            if (v.IsD())
                continue;
            const double q = double(v.cQ());
            if (!(q > 0) || !std::isfinite(q)) {
                if (bad++ == 0)
                    firstBad = q;
            }
            run.vertexDensity.push_back(q);
        }
        if (bad > 0)
            return fail(QString("FCVT: adaptive takes the density from the per-vertex quality, which "
                                "must be finite and > 0 at every vertex; %1 of %2 vertices of '%3' "
                                "are not (e.g. %4). Map it to positive values first (e.g. 'Per "
                                "Vertex Quality Function' with q = abs(q) + 0.1)")
                            .arg(bad)
                            .arg(run.vertexDensity.size())
                            .arg(input->label())
                            .arg(firstBad));
    }
    if (inputs.featuresFromSelection) {
        std::vector<char> selected;
        selected.reserve(in.faces.size());
        int selectedCount = 0;
        for (const CFaceO& f : input->cm.face)
            if (!f.IsD()) {
                selected.push_back(f.IsS() ? 1 : 0);
                selectedCount += f.IsS() ? 1 : 0;
            }
        run.featureEdges = selectionBorder(in, selected);
        if (run.featureEdges.empty())
            Log(GLLogStream::WARNING,
                QString("FCVT: featureSelection is on but the selection of '%1' (%2 of %3 faces) has "
                        "no border inside the mesh: no feature edges from it")
                    .arg(input->label())
                    .arg(selectedCount)
                    .arg(selected.size())
                    .toStdString());
        else
            Log(QString("FCVT features: %1 edges on the border of the %2 selected faces")
                    .arg(run.featureEdges.size())
                    .arg(selectedCount)
                    .toStdString());
    }

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
            // "FCVT: CVT iterations" in the status bar; MeshLab draws the percent beside it.
            const QByteArray label = stageLabel(stage).toUtf8();
            cb(p, label.constData());
        }
        return true;
    };

    const fieldcvt::RemeshResult result = fieldcvt::remesh(in, run, progress);

    // The new layer is created only once the core succeeded, so a failure leaves the document
    // as it was; a failure while filling it removes it again.
    const QString layerName = input->label() + " FCVT";
    MeshModel* output = md.addNewMesh("", layerName, true);
    try {
        fcvt_plugin::fromTriMesh(result.mesh, output->cm);
        if (!result.outputDirections.empty()) {
            if (result.outputDirections.size() != size_t(output->cm.vn))
                throw fieldcvt::Error("the output field has " +
                                      std::to_string(result.outputDirections.size()) +
                                      " directions for " + std::to_string(output->cm.vn) +
                                      " vertices");
            auto rosy = pointAttribute(output->cm, kRosyAttribute);
            for (size_t i = 0; i < result.outputDirections.size(); ++i)
                rosy[i] = toPoint3m(result.outputDirections[i]);
        }
        output->cm.Tr = input->cm.Tr;
        updateBoxAndNormals(*output);
        KeptData keep;
        keep.colour = input->hasDataMask(MeshModel::MM_VERTCOLOR);
        keep.quality = input->hasDataMask(MeshModel::MM_VERTQUALITY);
        keep.normals = input->hasDataMask(MeshModel::MM_VERTNORMAL);
        int mask = 0;
        if (keep.colour)
            mask |= MeshModel::MM_VERTCOLOR;
        if (keep.quality)
            mask |= MeshModel::MM_VERTQUALITY;
        if (mask != 0)
            output->updateDataMask(mask);
        // Vertex i of `in` is the i-th live vertex of the input layer (toTriMesh's order).
        std::vector<const CVertexO*> inVerts;
        inVerts.reserve(in.vertices.size());
        for (const CVertexO& v : input->cm.vert)
            if (!v.IsD())
                inVerts.push_back(&v);
        if (inVerts.size() != in.vertices.size())
            throw fieldcvt::Error("input vertex count changed during the filter");
        transferVertexData(in, inVerts, keep, output->cm);
        if (keep.colour || keep.quality)
            Log(QString("FCVT: per-vertex %1 of '%2' transferred to the output by closest point")
                    .arg(keep.colour && keep.quality ? "colour and quality"
                                                     : keep.colour ? "colour" : "quality")
                    .arg(input->label())
                    .toStdString());
        if (inputs.colorIrregular)
            Log(("FCVT valence colours on '" + output->label() + "': " +
                 applyValenceColours(result.mesh, *output))
                    .toStdString());
    } catch (...) {
        removeLayer(md, output);
        md.setCurrentMesh(input->id());
        throw;
    }
    if (cb != nullptr)
        cb(100, "FCVT done");
    logReport(result, output->label());
    if (run.valenceOptimization) {
        const fieldcvt::ValenceStats& v = result.valence;
        Log(QString("FCVT valence optimisation: V6% %1 -> %2, %3 flips, %4 collapses, %5 splits in %6 rounds")
                .arg(num(v.v6Before))
                .arg(num(v.v6After))
                .arg(v.flips)
                .arg(v.collapses)
                .arg(v.splits)
                .arg(v.rounds)
                .toStdString());
    } else {
        Log("FCVT valence optimisation: off");
    }
    Log(run.repair ? QString("FCVT repair: %1 (the counts are in the warnings)")
                         .arg(result.repair.notes.empty() ? "nothing to repair" : "done")
                         .toStdString()
                   : std::string("FCVT repair: off (strict input check)"));
    Log(QString("FCVT size: mean edge length %1 (%2 vertices)")
            .arg(num(meanEdgeLength(result.mesh)))
            .arg(result.mesh.vertexCount())
            .toStdString());
    if (result.outputDirections.empty())
        Log("FCVT field: none (lambda = 0 or no FCVT iterations)");
    else
        Log(QString("FCVT field: %1, %2 of the input; stored at the output vertices as the "
                    "per-vertex attribute '%3'")
                .arg(kFieldSources[fieldSourceIndex(run.fieldSource)].label)
                .arg(singularitySummary(result.singularities))
                .arg(kRosyAttribute)
                .toStdString());
    return true;
}

bool FilterRun::computeRosyField(MeshDocument& md, const fieldcvt::FieldParams& params,
                                        vcg::CallBackPos* cb)
{
    MeshModel* input = currentTriangleLayer(md);
    if (input == nullptr)
        return false;

    if (cb != nullptr)
        cb(0, "checking the input");
    const fieldcvt::TriMesh in = fcvt_plugin::toTriMesh(input->cm);
    fieldcvt::InputReport report;
    const fieldcvt::TriMesh clean = fieldcvt::prepareInput(in, report);
    if (report.cleanIndex.size() != in.vertices.size())
        throw fieldcvt::Error("the input check returned " + std::to_string(report.cleanIndex.size()) +
                              " vertex indices for " + std::to_string(in.vertices.size()) +
                              " vertices");
    if (cb != nullptr)
        cb(10, "computing the 6-RoSy field");
    const fieldcvt::DirectionField field = fieldcvt::computeField(clean, params);
    if (field.directions.size() != clean.vertices.size())
        throw fieldcvt::Error("the field has " + std::to_string(field.directions.size()) +
                              " directions for " + std::to_string(clean.vertices.size()) +
                              " vertices");
    if (cb != nullptr)
        cb(80, "finding singularities");
    const std::vector<fieldcvt::Singularity> singularities =
        fieldcvt::findSingularities(clean, field);

    // Everything is computed: now change the document. The drawing layer is removed again if
    // filling it fails; the attribute is written last.
    if (cb != nullptr)
        cb(90, "drawing the field");
    MeshModel* drawing = md.addNewMesh("", kFieldLayerLabel, false);
    fcvt_plugin::FieldDrawingStats stats;
    try {
        stats = fcvt_plugin::drawField(clean, field, drawing->cm);
        drawing->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_COLOR);
        drawing->cm.Tr = input->cm.Tr;
    } catch (...) {
        removeLayer(md, drawing);
        md.setCurrentMesh(input->id());
        throw;
    }

    auto rosy = pointAttribute(input->cm, kRosyAttribute);
    size_t live = 0;
    for (auto vi = input->cm.vert.begin(); vi != input->cm.vert.end(); ++vi) {
        if (vi->IsD())
            continue;
        const int c = report.cleanIndex[live++];
        rosy[vi] = c >= 0 ? toPoint3m(field.directions[size_t(c)]) : Point3m(0, 0, 0);
    }
    if (cb != nullptr)
        cb(100, "6-RoSy field done");

    for (const std::string& note : report.notes)
        Log(GLLogStream::WARNING, "FCVT input: " + note);
    Log(QString("FCVT field: %1 (seed %2) on layer '%3': %4; stored as the per-vertex attribute "
                "'%5'")
            .arg(kFieldSources[fieldSourceIndex(params.source)].label)
            .arg(qulonglong(params.seed))
            .arg(input->label())
            .arg(singularitySummary(singularities))
            .arg(kRosyAttribute)
            .toStdString());
    Log(QString("FCVT field: new layer '%1': %2 of %3 vertices drawn (every %4), %5 segments of "
                "length %6 (mean edge %7)")
            .arg(drawing->label())
            .arg(stats.drawnVertices)
            .arg(clean.vertexCount())
            .arg(stats.stride)
            .arg(3 * stats.drawnVertices)
            .arg(num(stats.segmentLength))
            .arg(num(stats.meanEdgeLength))
            .toStdString());
    return true;
}

bool FilterRun::qualityReport(MeshModel& mesh, MeshModel* reference, bool colorIrregular,
                                     vcg::CallBackPos* cb)
{
    if (reference != nullptr && reference->cm.fn == 0)
        return fail(QString("FCVT: the reference layer '%1' has no faces; choose a triangle mesh, or "
                            "the measured layer itself for no distances")
                        .arg(reference->label()));
    if (cb != nullptr)
        cb(0, "FCVT: measuring quality");
    const fieldcvt::TriMesh measured = fcvt_plugin::toTriMesh(mesh.cm);
    const fieldcvt::QualityMetrics quality = fieldcvt::computeQuality(measured);
    const fieldcvt::TopologySummary topology = fieldcvt::computeTopology(measured);
    fieldcvt::DistanceMetrics distance;
    if (reference != nullptr) {
        if (cb != nullptr)
            cb(20, "FCVT: measuring distances");
        const fieldcvt::TriMesh ref = fcvt_plugin::toTriMesh(reference->cm);
        distance = fieldcvt::computeDistance(measured, ref, distanceSamples(measured, ref));
    }
    // Measured before anything changes: a failure above leaves the layer as it was.
    QString colours;
    if (colorIrregular)
        colours = applyValenceColours(measured, mesh);
    if (cb != nullptr)
        cb(100, "FCVT: quality report done");

    Log(QString("FCVT quality of '%1': %2 vertices, %3 faces")
            .arg(mesh.label())
            .arg(quality.vertices)
            .arg(quality.faces)
            .toStdString());
    Log(("FCVT quality: " + qualityText(quality)).toStdString());
    if (reference != nullptr) {
        Log(QString("FCVT quality: d_RMS %1, d_H %2 (fractions of the bounding-box diagonal of '%3')")
                .arg(num(distance.rms))
                .arg(num(distance.hausdorff))
                .arg(reference->label())
                .toStdString());
        if (mesh.cm.Tr != reference->cm.Tr)
            Log(GLLogStream::WARNING,
                QString("FCVT quality: '%1' and '%2' have different transformation matrices; the "
                        "distances are between the stored coordinates")
                    .arg(mesh.label(), reference->label())
                    .toStdString());
    } else {
        Log("FCVT quality: d_RMS and d_H not measured (the reference layer is the measured layer)");
    }
    Log(("FCVT quality topology: " + topologyText(topology)).toStdString());
    if (colorIrregular)
        Log(("FCVT valence colours: " + colours).toStdString());
    return true;
}

void FilterRun::logReport(const fieldcvt::RemeshResult& r, const QString& layerName)
{
    const fieldcvt::QualityMetrics& m = r.metrics;
    Log(QString("FCVT: new layer '%1': %2 vertices, %3 faces, %4 energy evaluations")
            .arg(layerName)
            .arg(r.mesh.vertexCount())
            .arg(r.mesh.faceCount())
            .arg(r.evaluations)
            .toStdString());
    Log(QString("FCVT metrics: %1, d_RMS %2, d_H %3, d_boundary %4 (fractions of the input diagonal), "
                "boundary valence 4: %5%")
            .arg(qualityText(m))
            .arg(num(m.dRms))
            .arg(num(m.dH))
            .arg(num(m.dBoundary))
            .arg(num(m.boundaryV4Pct))
            .toStdString());
    if (r.valence.v6Before > 0 || r.valence.v6After > 0)
        Log(QString("FCVT valence optimisation: V6% %1 -> %2 (%3 flips, %4 collapses, %5 splits)")
                .arg(num(r.valence.v6Before))
                .arg(num(r.valence.v6After))
                .arg(r.valence.flips)
                .arg(r.valence.collapses)
                .arg(r.valence.splits)
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
    // E_CVT and E_field at the end of each phase (the last record of each).
    QString energies;
    for (size_t i = 0; i < r.energyHistory.size(); ++i) {
        const fieldcvt::EnergyRecord& e = r.energyHistory[i];
        if (i + 1 < r.energyHistory.size() && r.energyHistory[i + 1].phase == e.phase)
            continue;
        energies += QString("%1%2 E_CVT %3, E_field %4")
                        .arg(energies.isEmpty() ? "" : "; ")
                        .arg(QString::fromStdString(e.phase))
                        .arg(num(e.cvt, 6))
                        .arg(num(e.field, 6));
    }
    if (!energies.isEmpty())
        Log(("FCVT energy at the end of each phase: " + energies).toStdString());
    for (const std::string& w : r.warnings)
        Log(GLLogStream::WARNING, "FCVT warning: " + w);
}


}  // namespace
}  // namespace fcvt_plugin
