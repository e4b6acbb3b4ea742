#include "fcvt_filters.h"

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
#include <map>
#include <string>
#include <vector>

#include "closest_point.h"
#include "errors.h"
#include "field_of_input.h"
#include "field.h"
#include "field_drawing.h"
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

using fcvt_plugin::num;
using fcvt_plugin::parameterLabel;
using fcvt_plugin::parameterName;
using fcvt_plugin::plainLogText;
using fcvt_plugin::qualityText;
using fcvt_plugin::singularitySummary;
using fcvt_plugin::stageLabel;
using fcvt_plugin::topologyText;

// Upper end of the default vertexCount: the paper's typical output size (Table 1), and a run
// of a few seconds on two cores; inputs with fewer vertices default to their own count.
constexpr int kDefaultMaxVertices = 5000;

int defaultVertexCount(const MeshModel* m)
{
    const int vn = m != nullptr ? m->cm.vn : kDefaultMaxVertices;
    return std::max(fieldcvt::kMinVertexCount, std::min(vn, kDefaultMaxVertices));
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

// The adaptive enum, the density source (index = value in .mlx scripts, frozen). Scripts written
// before it was an enum carry adaptive as a bool: false = uniform, true = vertex quality.
enum DensityChoice { kDensityUniform = 0, kDensityCurvature = 1, kDensityVertexQuality = 2 };
const QStringList kDensityLabels = {"uniform", "curvature", "vertex quality"};

// A parameter that a script may lack (added after the first release): its value, or `fallback`.
bool boolParam(const ParamValues& par, const char* key, bool fallback)
{
    return par.hasParameter(key) ? par.getBool(key) : fallback;
}

double floatParam(const ParamValues& par, const char* key, double fallback)
{
    return par.hasParameter(key) ? double(par.getFloat(key)) : fallback;
}

// The density source: the adaptive enum, or the bool of scripts from before it was one
// (true = vertex quality); uniform when the script has neither.
int densityChoice(const ParamValues& par)
{
    if (!par.hasParameter(kAdaptive)) return kDensityUniform;
    if (par.isBool(kAdaptive)) return par.getBool(kAdaptive) ? kDensityVertexQuality : kDensityUniform;
    return par.getEnum(kAdaptive);
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
    for (int i = 0; i < count; ++i) labels << kFieldSources[i].label;
    return labels;
}

int fieldSourceIndex(fieldcvt::FieldSource source)
{
    for (int i = 0; i < kAllFieldSources; ++i)
        if (kFieldSources[i].source == source) return i;
    return 0;
}

fieldcvt::Vec3 toVec3(const Point3m& p) { return fieldcvt::Vec3(double(p[0]), double(p[1]), double(p[2])); }

Point3m toPoint3m(const fieldcvt::Vec3& v) { return Point3m(Scalarm(v.x()), Scalarm(v.y()), Scalarm(v.z())); }

// A handle to the per-vertex Point3m attribute `name`, created if missing; an attribute of that
// name but another type is replaced (vcg asserts on adding a name that exists).
CMeshO::PerVertexAttributeHandle<Point3m> pointAttribute(CMeshO& cm, const char* name)
{
    auto h = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(cm, name);
    if (vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(cm, h)) return h;
    vcg::tri::Allocator<CMeshO>::DeletePerVertexAttribute(cm, name);
    return vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<Point3m>(cm, name);
}

// The name of the remeshing's new layer: the input's label without its extension and with no
// dot, then "_FCVT" ("bunny.off" -> "bunny_FCVT"). MeshLab's layer list shows a label up to its
// last dot (QFileInfo::completeBaseName), so "bunny.off FCVT" read "bunny", like its input; a
// rerun gets "bunny_FCVT(1)" from MeshLab's own disambiguation.
QString outputLayerName(const QString& inputLabel)
{
    QString base = QFileInfo(inputLabel).completeBaseName();
    if (base.isEmpty()) base = inputLabel;
    base.replace(QChar('.'), QChar('_'));
    return base + "_FCVT";
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
        if (!v.IsD() && i < c.colours.size()) v.C() = c.colours[i++];
    if (i != c.colours.size()) throw fieldcvt::Error("valence colours: vertex count mismatch");
    return fcvt_plugin::valenceColourText(c);
}

// Feature lines from a face selection: the edges between a selected and an unselected face
// (vertex indices of `mesh`, whose face i is the i-th live face, `selected[i]` its flag).
std::vector<std::array<int, 2>> selectionBorder(const fieldcvt::TriMesh& mesh, const std::vector<char>& selected)
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
        if (count.second > 0 && count.second < count.first) border.push_back({edge.first, edge.second});
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
void transferVertexData(const fieldcvt::TriMesh& in, const std::vector<const CVertexO*>& inVerts, const KeptData& keep,
                        CMeshO& out)
{
    if (!keep.any() || in.faces.empty()) return;
    const fieldcvt::ClosestPointTree tree(in);
    for (CVertexO& v : out.vert) {
        if (v.IsD()) continue;
        const fieldcvt::ClosestPoint cp = tree.closest(toVec3(v.cP()));
        if (cp.face < 0) continue;
        const fieldcvt::Face& f = in.faces[size_t(cp.face)];
        const CVertexO* c[3] = {inVerts[size_t(f[0])], inVerts[size_t(f[1])], inVerts[size_t(f[2])]};
        const double w[3] = {cp.barycentric.x(), cp.barycentric.y(), cp.barycentric.z()};
        if (keep.colour) {
            for (int ch = 0; ch < 4; ++ch) {
                double x = 0;
                for (int k = 0; k < 3; ++k) x += w[k] * double(c[k]->cC()[ch]);
                v.C()[ch] = static_cast<unsigned char>(std::clamp(std::lround(x), 0L, 255L));
            }
        }
        if (keep.quality) {
            double q = 0;
            for (int k = 0; k < 3; ++k) q += w[k] * double(c[k]->cQ());
            v.Q() = static_cast<float>(q);
        }
        if (keep.normals) {
            fieldcvt::Vec3 n(0, 0, 0);
            for (int k = 0; k < 3; ++k) n += w[k] * toVec3(c[k]->cN());
            const double len = n.norm();
            if (std::isfinite(len) && len > 1e-12) v.N() = toPoint3m(n / len);
        }
    }
}

// The parameter declarations below read like both MeshLabs' own (par.addParam(RichInt(...)));
// these build the neutral ParamDef the glue turns into its MeshLab's Rich* parameters.
struct ParamList {
    std::vector<ParamDef> defs;
    void addParam(ParamDef p) { defs.push_back(std::move(p)); }
};

ParamDef makeParam(ParamDef::Type type, const char* name, double value, const QString& label, const QString& tooltip)
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
ParamDef RichEnum(const char* name, int value, const QStringList& labels, const QString& label, const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::Enum, name, value, label, tooltip);
    p.enumLabels = labels;
    return p;
}
ParamDef RichAbsPerc(const char* name, float value, float min, float max, const QString& label, const QString& tooltip)
{
    ParamDef p = makeParam(ParamDef::AbsPerc, name, double(value), label, tooltip);
    p.min = double(min);
    p.max = double(max);
    return p;
}
//! Marks a parameter few users change (ParamDef::advanced).
ParamDef advanced(ParamDef p)
{
    p.advanced = true;
    return p;
}
ParamDef RichMesh(const char* name, const MeshModel*, const MeshDocument*, const QString& label, const QString& tooltip)
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
        bool densityFromQuality = false;     //!< adaptive: ρ = per-vertex quality
        bool featuresFromSelection = false;  //!< feature lines = border of the face selection
        bool colorIrregular = false;         //!< colour the output's vertices by valence
    };
    //! The typed body of "Remeshing: Field-Aligned CVT (FCVT)".
    bool remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, const RemeshInputs& inputs, vcg::CallBackPos* cb);
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

    //! Log lines (info / warning, shown red in the GUI) through plainLogText(), so that MeshLab's
    //! HTML log shows all of their text.
    void logInfo(const QString& line);
    void logWarning(const QString& line);
    //! The layer's mesh for remeshing or a field (fcvt_plugin::toSurfaceMesh), with the
    //! zero-area triangles it flipped logged.
    //! The layer as the core's mesh, with its file's double coordinates when it is as read, and
    //! the file's triangulation of polygons unless `keepFaces` (face selection in use).
    fieldcvt::TriMesh surfaceOf(const MeshModel& layer, bool keepFaces = false);

    FilterLog& log_;
};

void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par);

}  // namespace

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
        // Kept to three lines: MeshLab shows it above the parameters, and Qt gives the dialog at
        // most 2/3 of the screen's height (682 pixels at 1280x1024), below which MeshLab 2020.09
        // clips the last row. What each parameter does is in its tooltip (the Help button).
        return "Isotropic remeshing into a new layer: a centroidal Voronoi tessellation of the "
               "surface with edges aligned to a 6-RoSy field, then valence optimisation (<b>\"Field-"
               "Aligned Isotropic Surface Remeshing\"</b>). Figures and times go to the log.";
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

namespace {

void addParameters(FilterId a, const MeshDocument* md, const MeshModel* m, ParamList& par)
{
    const int vertexCountDefault = defaultVertexCount(m);
    const float diagonal = bboxDiagonal(m);
    switch (a) {
    case kRemesh: {
        // Core defaults are the single source of truth for everything but vertexCount.
        const fieldcvt::RemeshParams defaults;
        // The dialog's order: what most runs set first, the optimiser's knobs after. Scripts
        // match parameters by name (RichParameterList::getParameterByName), so the order is free;
        // a new parameter still goes at the end, where meshlabserver adds a missing one.
        par.addParam(RichInt(kVertexCount, vertexCountDefault, parameterLabel(kVertexCount),
                             "Number of output vertices (Voronoi samples), at least 4. Default: "
                             "the input's vertex count, capped at 5000."));
        par.addParam(RichEnum(kSizeMode, kSizeByVertexCount, kSizeModeLabels, parameterLabel(kSizeMode),
                              "How the output size is given: by the number of vertices (Target "
                              "vertices) or by the edge length (Target edge length), converted to "
                              "a vertex count through the surface area."));
        par.addParam(RichAbsPerc(kTargetLength, 0.01f * diagonal, 0.0f, diagonal, parameterLabel(kTargetLength),
                                 "Wanted edge length in world units (used when Size by is 'target "
                                 "edge length'); the vertex count is about 2 * area / (sqrt(3) * "
                                 "length^2). Default: 1% of the bounding-box diagonal."));
        par.addParam(RichEnum(kAdaptive, kDensityUniform, kDensityLabels, parameterLabel(kAdaptive),
                              "Where the vertices go, the vertex count unchanged: uniform; more where "
                              "the surface bends (curvature, graded by Curvature gradation); or more "
                              "where the input's per-vertex quality is higher (every value must be "
                              "finite and above 0)."));
        par.addParam(advanced(RichFloat(kGradation, float(defaults.gradation), parameterLabel(kGradation),
                                        "With Vertex density 'curvature': how strongly curvature raises the "
                                        "density (0 or more; 0 = uniform, 1 = edges up to about 3 times "
                                        "shorter where the surface bends most).")));
        par.addParam(RichFloat(kFeatureAngle, float(defaults.featureAngleDegrees), parameterLabel(kFeatureAngle),
                               "Input edges whose faces meet at a dihedral angle of at least this "
                               "many degrees are sharp features that the output follows; 0 = no "
                               "sharp features (0..180)."));
        par.addParam(RichBool(kValenceOptimization, defaults.valenceOptimization, parameterLabel(kValenceOptimization),
                              "After the extraction, edge flips, collapses and splits that bring "
                              "vertices to valence 6 (4 on boundaries), then a relaxation that "
                              "realigns the edges (paper section 4.4)."));
        par.addParam(advanced(RichBool(kColorIrregular, false, parameterLabel(kColorIrregular),
                                       "Colour the output's vertices by valence: blue below 6 (4 on a "
                                       "boundary), pink above, white at it. Replaces the colour carried "
                                       "over from the input.")));
        par.addParam(advanced(RichFloat(kLambda, float(defaults.lambda), parameterLabel(kLambda),
                                        "Weight of the field-alignment energy; 0 gives a pure isotropic "
                                        "CVT.")));
        par.addParam(advanced(RichEnum(kFieldSource, fieldSourceIndex(defaults.fieldSource), fieldSourceLabels(kAllFieldSources),
                                       parameterLabel(kFieldSource),
                                       "The 6-RoSy field the edges are aligned to: the extrinsically smooth "
                                       "field, the max or min principal-curvature direction, or the "
                                       "per-vertex Point3 attribute 'rosy' of the input layer.")));
        par.addParam(advanced(RichInt(kSeed, int(defaults.seed), parameterLabel(kSeed),
                                      "Seed of the initial sampling (0 or more); the same seed gives the same "
                                      "output.")));
        par.addParam(advanced(RichInt(kCvtIterations, defaults.cvtIterations, parameterLabel(kCvtIterations),
                                      "L-BFGS iterations on the CVT energy (the paper uses 130).")));
        par.addParam(advanced(RichInt(kFcvtIterations, defaults.fcvtIterations, parameterLabel(kFcvtIterations),
                                      "L-BFGS iterations on CVT + lambda * field energy, run after the CVT "
                                      "iterations.")));
        par.addParam(advanced(RichBool(kFeatureSelection, false, parameterLabel(kFeatureSelection),
                                       "Also treat the border of the input's face selection (edges between a "
                                       "selected and an unselected face) as feature lines.")));
        // Added after issue 15's reordering (issue 17): at the end, like every new parameter.
        par.addParam(RichBool(kRepair, defaults.repair, parameterLabel(kRepair),
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
        par.addParam(RichEnum(kFieldSource, fieldSourceIndex(defaults.source), fieldSourceLabels(kComputedFieldSources),
                              parameterLabel(kFieldSource),
                              "The extrinsically smooth 6-RoSy field (aligned to boundaries and "
                              "sharp edges), or the max or min principal-curvature direction."));
        par.addParam(RichInt(kSeed, int(defaults.seed), parameterLabel(kSeed),
                             "Seed of the random initial directions of the smooth field (0 or more); "
                             "the same seed gives the same field."));
        par.addParam(RichInt(kMaxCrosses, kDefaultMaxCrosses, parameterLabel(kMaxCrosses),
                             "The drawing layer shows the field as a cross at every vertex, or at "
                             "one vertex per cell of a grid when the mesh has more vertices than "
                             "this (at least 1)."));
        break;
    }
    case kQuality: {
        // The default reference is the measured layer itself, which means "no distances".
        const QString description = parameterLabel(kReferenceLayer);
        const char* tooltip =
            "The layer d_RMS and d_H are measured against (e.g. the input of the "
            "remeshing). The current layer itself: no distances.";
        if (md != nullptr && m != nullptr)
            par.addParam(RichMesh(kReferenceLayer, m, md, description, tooltip));
        else  // no document: a parameter without a mesh (only for completeness of the overload)
            par.addParam(RichMesh(kReferenceLayer, static_cast<MeshModel*>(nullptr), nullptr, description, tooltip));
        par.addParam(RichBool(kColorIrregular, true, parameterLabel(kColorIrregular),
                              "Colour the vertices by valence: blue below 6 (4 on a boundary), "
                              "pink above, white at it."));
        break;
    }
    default: break;
    }
}

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
    if (sizeMode == kSizeByTargetLength) {
        MeshModel* input = currentTriangleLayer(md);
        if (input == nullptr) return false;
        // In double and scale-robust (a float cross product overflows from coordinates ~1e10).
        const double area = fieldcvt::surfaceArea(fcvt_plugin::toTriMesh(input->cm));
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

    fieldcvt::RemeshParams params;
    params.vertexCount = vertexCount;
    params.lambda = lambda;
    params.cvtIterations = cvtIterations;
    params.fcvtIterations = fcvtIterations;
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
    return remeshFcvt(md, params, inputs, cb);
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

bool FilterRun::remeshFcvt(MeshDocument& md, const fieldcvt::RemeshParams& params, const RemeshInputs& inputs,
                           vcg::CallBackPos* cb)
{
    MeshModel* input = currentTriangleLayer(md);
    if (input == nullptr) return false;

    fieldcvt::TriMesh in = surfaceOf(*input, inputs.featuresFromSelection);
    fieldcvt::RemeshParams run = params;
    run.outputInFloat = sizeof(Scalarm) == sizeof(float);  // the new layer's coordinates
    if (run.fieldSource == fieldcvt::FieldSource::User) {
        // One vector per live vertex, in the order of toTriMesh.
        // Not const: vcg's handle has no const operator[].
        auto rosy = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<Point3m>(input->cm, kRosyAttribute);
        if (!vcg::tri::Allocator<CMeshO>::IsValidHandle<Point3m>(input->cm, rosy))
            return fail(QString("FCVT: %1 'per-vertex attribute rosy' needs the per-vertex "
                                "Point3 attribute '%2' on layer '%3', which has none (run 'Compute "
                                "6-RoSy Field' on it first)")
                            .arg(parameterName(kFieldSource))
                            .arg(kRosyAttribute)
                            .arg(input->label()));
        run.userDirections.clear();
        run.userDirections.reserve(in.vertices.size());
        for (auto vi = input->cm.vert.begin(); vi != input->cm.vert.end(); ++vi)
            if (!vi->IsD()) run.userDirections.push_back(toVec3(rosy[vi]));
    }
    if (inputs.densityFromQuality) {
        if (!input->hasDataMask(MeshModel::MM_VERTQUALITY))
            return fail(QString("FCVT: %1 'vertex quality' needs per-vertex quality on layer '%2', "
                                "which has none (compute one first, e.g. with 'Discrete Curvatures' or "
                                "'Per Vertex Quality Function', then make it positive)")
                            .arg(parameterName(kAdaptive))
                            .arg(input->label()));
        run.density = fieldcvt::DensitySource::PerVertex;
        run.vertexDensity.clear();
        run.vertexDensity.reserve(in.vertices.size());
        int bad = 0;
        double firstBad = 0;
        for (const CVertexO& v : input->cm.vert) {
            if (v.IsD()) continue;
            const double q = double(v.cQ());
            if (!(q > 0) || !std::isfinite(q)) {
                if (bad++ == 0) firstBad = q;
            }
            run.vertexDensity.push_back(q);
        }
        if (bad > 0)
            return fail(QString("FCVT: %1 'vertex quality' takes the density from the per-vertex "
                                "quality, which must be finite and above 0 at every vertex; %2 of %3 "
                                "vertices of '%4' are not (e.g. %5). Map it to positive values first "
                                "(e.g. 'Per Vertex Quality Function' with q = abs(q) + 0.1)")
                            .arg(parameterName(kAdaptive))
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
            logWarning(QString("FCVT: %1 is on but the selection of '%2' (%3 of %4 faces) has "
                               "no border inside the mesh: no feature edges from it")
                           .arg(parameterName(kFeatureSelection))
                           .arg(input->label())
                           .arg(selectedCount)
                           .arg(selected.size()));
        else
            logInfo(QString("FCVT features: %1 edges on the border of the %2 selected faces")
                        .arg(run.featureEdges.size())
                        .arg(selectedCount));
    }

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

    const fieldcvt::RemeshResult result = fieldcvt::remesh(in, run, progress);

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
        if (keep.colour || keep.quality)
            outputLines.push_back(QString("FCVT: per-vertex %1 of '%2' transferred to the output by closest point")
                                      .arg(keep.colour && keep.quality ? "colour and quality"
                                           : keep.colour               ? "colour"
                                                                       : "quality")
                                      .arg(input->label()));
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
    for (const QString& line : outputLines) logInfo(line);
    return true;
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

}  // namespace
}  // namespace fcvt_plugin
