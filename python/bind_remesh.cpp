// fcvt.remesh(V, F, **options): the `fcvt remesh` command over arrays, its options and report
// from frontend/ (the same code as the CLI's).
#include "arrays.h"
#include "bindings.h"
#include "keyword_options.h"
#include "progress_bridge.h"
#include "remesh_options.h"
#include "remesh_report.h"
#include "report.h"

#include "errors.h"
#include "metrics.h"
#include "region.h"
#include "remesh.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace fieldcvt::python {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

//! What fcvt.remesh returns.
struct RemeshOutput {
    py::object vertices, faces;           //!< n x 3 float64, m x 3 int32
    py::object normals, rosy;             //!< n x 3 float64 when a field was used (as a PLY OUT carries), else None
    py::object report;                    //!< the --report JSON as a dict
    py::object warnings;                  //!< list of str (also issued as UserWarning)
    py::object vertexOrigin, faceOrigin;  //!< with region=: the input's index, -1 for new ones; else None
};

//! The user field (--field user): the CLI's takes it from the PLY, the module from rosy=.
std::vector<Vec3> userDirections(const py::object& rosy, FieldSource source, size_t vertexCount)
{
    if (source != FieldSource::User) {
        if (!rosy.is_none()) throw frontend::UsageError("rosy= is the field of field='user' only");
        return {};
    }
    if (rosy.is_none()) throw frontend::UsageError("--field user takes the field from rosy= (n x 3, one vector per vertex of V)");
    std::vector<Vec3> vectors = vectorsFromArray(rosy, "rosy");
    if (vectors.size() != vertexCount)
        throw InvalidInputError("rosy has " + std::to_string(vectors.size()) + " vectors for " + std::to_string(vertexCount) +
                                " vertices");
    for (size_t v = 0; v < vectors.size(); ++v)
        if (!vectors[v].allFinite()) throw InvalidInputError("vertex " + std::to_string(v) + " has a non-finite rosy vector");
    return vectors;
}

std::vector<char> regionFlags(const py::object& region, size_t faceCount)
{
    if (region.is_none()) return {};
    std::vector<char> selected = flagsFromArray(region, faceCount, "region");
    if (std::none_of(selected.begin(), selected.end(), [](char c) { return c != 0; }))
        throw InvalidInputError("the region is empty: no face has a non-zero value in region=");
    return selected;
}

py::array_t<int> originArray(const std::vector<int>& origin)
{
    py::array_t<int> out(py::ssize_t(origin.size()));
    std::copy(origin.begin(), origin.end(), out.mutable_data());
    return out;
}

RemeshOutput remeshArrays(const py::handle& V, const py::handle& F, const py::object& progress, const py::object& region,
                          const py::object& rosy, const py::kwargs& keywords)
{
    const auto start = Clock::now();
    const frontend::Arguments a = argumentsFromKeywords(keywords, frontend::remeshOptionNames());
    frontend::RemeshOptions options = frontend::remeshOptions(a);
    RemeshParams& params = options.params;
    // Result.report is what --report writes: the distances and singularities computed as then.
    params.computeDistances = params.computeSingularities = true;
    frontend::textureMethodFromText(a.text("texture").value_or("auto"));  // checked; arrays carry no texture
    const TriMesh input = meshFromArrays(V, F);
    const std::vector<char> selected = regionFlags(region, input.faces.size());
    params.userDirections = userDirections(rosy, params.fieldSource, input.vertices.size());
    const std::string sizeWarning = frontend::applyTargetLength(options, frontend::sizedArea(input, selected));
    const double readSeconds = secondsSince(start);

    ProgressBridge bridge(progress);
    RegionRemeshResult run;
    frontend::RunFigures figures;
    bool cancelled = false;
    {
        py::gil_scoped_release release;
        try {
            if (!selected.empty())
                run = remeshRegion(input, selected, params, RegionParams{}, bridge.callback());
            else
                run.result = remesh(input, params, bridge.callback());
            figures.outputTopology = computeTopology(run.result.mesh);
            figures.meanEdge = meanEdgeLength(run.result.mesh);
        } catch (const CancelledError&) {
            cancelled = true;
        }
    }
    if (cancelled) {
        bridge.rethrowIfFailed();
        throw CancelledError();
    }
    const RemeshResult& result = run.result;
    std::vector<std::string> warnings;
    if (!sizeWarning.empty()) warnings.push_back(sizeWarning);
    warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
    figures.readSeconds = readSeconds;
    figures.totalSeconds = secondsSince(start);
    nlohmann::ordered_json report =
        frontend::remeshReport(nullptr, nullptr, params, options.targetLength, result, figures, warnings, result.notes,
                               selected.empty() ? nlohmann::ordered_json(nullptr) : frontend::regionJson("region", run));
    report["texture"] = frontend::textureSummaryJson(false, a.flag("no-texture"), false);
    if (const auto reportPath = a.text("report")) frontend::writeJsonFile(*reportPath, report);

    RemeshOutput out;
    out.vertices = verticesArray(result.mesh.vertices);
    out.faces = facesArray(result.mesh.faces);
    const size_t n = result.mesh.vertices.size();
    const bool field =
        !result.outputDirections.empty() && result.outputDirections.size() == n && result.outputNormals.size() == n;
    out.normals = field ? py::object(verticesArray(result.outputNormals)) : py::none();
    out.rosy = field ? py::object(verticesArray(result.outputDirections)) : py::none();
    out.report = toPython(report);
    out.warnings = py::cast(warnings);
    out.vertexOrigin = selected.empty() ? py::none() : py::object(originArray(run.vertexOrigin));
    out.faceOrigin = selected.empty() ? py::none() : py::object(originArray(run.faceOrigin));
    issueWarnings(warnings);
    return out;
}

const char* const remeshDoc = R"doc(remesh(V, F, *, progress=None, region=None, rosy=None, **options) -> Result

Remeshes the triangle mesh (V: n x 3 coordinates, F: m x 3 vertex indices) as
`fcvt remesh IN OUT` does. Every option of `fcvt remesh` is a keyword: `-` becomes `_`,
flags are bools, `lambda` is `lambda_` (e.g. vertices=5000, target_length=0.01, seed=1,
lambda_=0, feature_angle=45, no_valence=True, preset="fast"); exactly one of vertices and
target_length.
region: one value per face, non-zero = remeshed (the CLI's --region). rosy: n x 3, the field
of field='user'. progress: callable(stage: str, percent: int), called as the run goes.
Returns a Result: vertices (float64), faces (int32), normals and rosy (the field at the
output's vertices, or None), report (the dict of --report), warnings (list of str).
Raises ValueError for bad input or options (the CLI's message), KeyboardInterrupt on Ctrl-C.
)doc";

}  // namespace

void bindRemesh(py::module_& m)
{
    py::class_<RemeshOutput>(m, "Result", "What fcvt.remesh returns.")
        .def_readonly("vertices", &RemeshOutput::vertices, "n x 3 float64: the output's vertices")
        .def_readonly("faces", &RemeshOutput::faces, "m x 3 int32: the output's triangles")
        .def_readonly("normals", &RemeshOutput::normals, "n x 3 float64: unit normals where the field was used, else None")
        .def_readonly("rosy", &RemeshOutput::rosy, "n x 3 float64: the 6-RoSy field's representative, else None")
        .def_readonly("report", &RemeshOutput::report, "dict: the keys of `fcvt remesh --report`")
        .def_readonly("warnings", &RemeshOutput::warnings, "list of str: the run's warnings")
        .def_readonly("vertex_origin", &RemeshOutput::vertexOrigin, "with region=: input vertex per output vertex (-1 new)")
        .def_readonly("face_origin", &RemeshOutput::faceOrigin, "with region=: input face per output face (-1 new)")
        .def("__repr__", [](const RemeshOutput& r) {
            return "<fcvt.Result: " + std::to_string(py::len(r.vertices)) + " vertices, " + std::to_string(py::len(r.faces)) +
                   " faces>";
        });
    m.def("remesh", &remeshArrays, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("progress") = py::none(),
          py::arg("region") = py::none(), py::arg("rosy") = py::none(), remeshDoc);
}

}  // namespace fieldcvt::python
