// The filters' names, descriptions and kinds, their parameters' declaration and the dispatch of
// a run (fcvt_filters.h).
#include "fcvt_filters.h"

#include <charconv>
#include <cmath>
#include <exception>
#include <system_error>
#include <utility>
#include <vector>

#include "errors.h"
#include "filter_parameters.h"
#include "filter_run.h"
#include "log_text.h"

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
        // Kept to one line: MeshLab shows it above the parameters, and Qt gives the dialog at
        // most 2/3 of the screen's height (682 pixels at 1280x1024), below which MeshLab 2020.09
        // clips the last row (17 rows since exactCount; 18 since preset, 702 pixels where the CTest
        // measures, docs/meshlab.md). What each parameter does is in its tooltip (the Help button).
        return "<b>Field-Aligned Isotropic Surface Remeshing</b> into a new layer.";
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

FilterOutput applyFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log, Callback* cb, bool figures)
{
    FilterRun run(log, figures);
    switch (filter) {
    case kRemesh: run.applyRemesh(md, par, cb); break;
    case kField: run.applyField(md, par, cb); break;
    case kQuality: run.applyQuality(md, par, cb); break;
    default: throw FilterFailure("FCVT: unknown filter");
    }
    return run.output();
}

QString unexpectedFailure(const std::exception* e)
{
    // Escaped: an exception's text may quote the input (a name, a token) and must not reach the
    // log as raw control characters.
    return e != nullptr ? QString("FCVT: %1").arg(QString::fromStdString(fieldcvt::escapeControlCharacters(e->what())))
                        : QString("FCVT: unknown error");
}

bool runFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log, Callback* cb, QString& failure,
               FilterOutput* output)
{
    try {
        FilterOutput figures = applyFilter(filter, md, par, log, cb, output != nullptr);
        if (output != nullptr) *output = std::move(figures);
        return true;
    } catch (const FilterFailure& e) {
        failure = e.message();
    } catch (const std::exception& e) {
        failure = unexpectedFailure(&e);
    } catch (...) {
        failure = unexpectedFailure(nullptr);
    }
    failure = plainLogText(failure);
    log.warning(failure);
    return false;
}

}  // namespace fcvt_plugin
