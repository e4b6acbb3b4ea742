#include "remesh_options.h"

#include "errors.h"
#include "remesh_limits.h"
#include "remesh_presets.h"

namespace fieldcvt::frontend {

const OptionNames& remeshOptionNames()
{
    static const OptionNames names{
        {"vertices", "target-length", "field", "lambda", "lloyd-iterations", "cvt-iterations", "fcvt-iterations", "seed",
         "threads", "time-limit", "report", "feature-angle", "adaptive", "gradation", "region", "texture", "preset"},
        {"quiet", "help", "no-valence", "no-repair", "keep-holes", "exact-count", "full-surface", "random-start", "no-texture",
         "overwrite"}};
    return names;
}

const OptionNames& fieldOptionNames()
{
    static const OptionNames names{{"field", "seed"}, {"quiet", "help"}};
    return names;
}

FieldSource fieldOption(const Arguments& a, FieldSource fallback, bool allowUser)
{
    const auto name = a.text("field");
    if (!name) return fallback;
    const std::string valid =
        allowUser ? "extrinsic, curvature-max, curvature-min or user" : "extrinsic, curvature-max or curvature-min";
    FieldSource source;
    try {
        source = fieldSourceFromName(*name);
    } catch (const InvalidInputError&) {
        throw UsageError("--field must be " + valid + ", got " + quoteInput(*name));
    }
    if (source == FieldSource::User && !allowUser) throw UsageError("--field must be " + valid + ", got " + quoteInput(*name));
    return source;
}

void checkOptions(const RemeshParams& params)
{
    ParameterNames names;
    names.vertexCount = "--vertices";
    names.lambda = "--lambda";
    names.lloydIterations = "--lloyd-iterations";
    names.cvtIterations = "--cvt-iterations";
    names.fcvtIterations = "--fcvt-iterations";
    names.threads = "--threads";
    names.timeLimit = "--time-limit";
    names.featureAngle = "--feature-angle";
    names.gradation = "--gradation";
    try {
        checkRemeshParams(params, names);
    } catch (const InvalidInputError& e) {
        throw UsageError(e.what());
    }
}

TextureMethod textureMethodFromText(const std::string& text)
{
    if (text == "auto") return TextureMethod::Auto;
    if (text == "keep") return TextureMethod::Keep;
    if (text == "bake") return TextureMethod::Bake;
    throw UsageError("--texture must be auto, keep or bake (got '" + text + "')");
}

namespace {

//! The options as the core's parameters: the syntax checked here, the ranges by the core's one
//! check (checkRemeshParams) in the options' names, as a usage error before any work.
RemeshParams paramsFrom(const Arguments& a)
{
    if (a.has("vertices") == a.has("target-length"))
        throw UsageError(
            "remesh needs exactly one of --vertices N (the target vertex count) and --target-length L "
            "(the target edge length)");
    RemeshParams p;
    // The preset first: every other option overrides what it sets.
    if (const auto preset = a.text("preset")) {
        try {
            applyPreset(p, presetFromName(*preset));
        } catch (const InvalidInputError&) {
            throw UsageError("--preset must be fast, default or quality, got " + quoteInput(*preset));
        }
    }
    p.vertexCount = a.saturatedInt("vertices", p.vertexCount);
    p.fieldSource = fieldOption(a, p.fieldSource, true);
    p.lambda = a.number("lambda", p.lambda);
    if (a.has("lloyd-iterations"))  // from either start
        p.lloydIterations = p.latticeLloydIterations = a.saturatedInt("lloyd-iterations", p.lloydIterations);
    p.cvtIterations = a.saturatedInt("cvt-iterations", p.cvtIterations);
    if (a.has("fcvt-iterations"))  // at any size
        p.fcvtIterations = p.largeRunFcvtIterations = a.saturatedInt("fcvt-iterations", p.fcvtIterations);
    p.seed = a.unsignedInteger("seed", p.seed);
    p.threads = a.saturatedInt("threads", p.threads);
    p.timeLimitSeconds = a.number("time-limit", p.timeLimitSeconds);
    p.valenceOptimization = !a.flag("no-valence");
    p.latticeStart = !a.flag("random-start");
    if (a.flag("full-surface")) p.optimisationFacesPerSample = 0;
    p.repair = !a.flag("no-repair");
    if (a.flag("keep-holes")) p.closeHolesUnder = 0;
    p.exactCount = a.flag("exact-count");
    p.featureAngleDegrees = a.number("feature-angle", p.featureAngleDegrees);
    if (const auto adaptive = a.text("adaptive")) {
        if (*adaptive == "curvature")
            p.density = DensitySource::Curvature;
        else if (*adaptive == "none")
            p.density = DensitySource::Uniform;
        else
            throw UsageError("--adaptive must be 'curvature' or 'none', got " + quoteInput(*adaptive));
    }
    if (a.has("gradation") && p.density != DensitySource::Curvature)
        throw UsageError("--gradation applies to --adaptive curvature only");
    p.gradation = a.number("gradation", p.gradation);
    checkOptions(p);
    return p;
}

}  // namespace

RemeshOptions remeshOptions(const Arguments& a)
{
    RemeshOptions options;
    options.params = paramsFrom(a);
    // Checked before reading the input (a usage error); applied once the area is known.
    options.targetLength = a.number("target-length", 0.0, 0.0, Arguments::Bound::Exclusive);
    options.quiet = a.flag("quiet");
    options.report = a.has("report");
    // The distances (dense sampling of both meshes: 0.05-0.26 s on the benchmark rows) are
    // only ever printed or reported; the quality figures and the topology check stay.
    if (options.quiet && !options.report) options.params.computeDistances = false;
    options.params.computeSingularities = options.report;  // only the report lists them
    return options;
}

std::string applyTargetLength(RemeshOptions& options, double area)
{
    if (options.targetLength <= 0) return {};
    try {
        const VertexCountFromLength size = vertexCountForLength(area, options.targetLength, "--target-length");
        options.params.vertexCount = size.vertexCount;
        return size.warning;
    } catch (const InvalidInputError& e) {
        throw UsageError(e.what());  // an argument that does not fit this input: a usage error, as before
    }
}

double sizedArea(const TriMesh& input, const std::vector<char>& selected)
{
    if (selected.empty()) return surfaceArea(input);
    double area = 0;
    for (int f = 0; f < input.faceCount(); ++f) area += selected[size_t(f)] ? faceArea(input, f) : 0.0;
    return area;
}

FieldParams fieldParams(const Arguments& a)
{
    FieldParams params;
    params.source = fieldOption(a, params.source, true);
    params.seed = a.unsignedInteger("seed", params.seed);
    return params;
}

}  // namespace fieldcvt::frontend
