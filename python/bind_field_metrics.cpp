// fcvt.field(V, F, **options) and fcvt.metrics(V, F, reference=...): `fcvt field` and `fcvt
// metrics --json [--ref]` over arrays, with the CLI's option parsing and JSON (frontend/).
#include "arrays.h"
#include "bindings.h"
#include "keyword_options.h"
#include "metrics_report.h"
#include "remesh_options.h"

#include "errors.h"
#include "field_of_input.h"
#include "metrics.h"

#include <string>
#include <vector>

namespace fieldcvt::python {

namespace {

//! What fcvt.field returns: the checked (and repaired) input, as `fcvt field` writes it, and
//! its field per vertex.
struct FieldOutput {
    py::object vertices, faces, normals, rosy;
    py::object singularities;  //!< k x 3 float64 positions
    py::object indices;        //!< k int32: each singularity's index in sixths of a turn
    long long indexSum = 0;
    long long eulerCharacteristic = 0;
    py::object warnings;
};

FieldOutput fieldArrays(const py::handle& V, const py::handle& F, const py::object& rosy, const py::kwargs& keywords)
{
    const frontend::Arguments a = argumentsFromKeywords(keywords, frontend::fieldOptionNames());
    const FieldParams params = frontend::fieldParams(a);
    const TriMesh input = meshFromArrays(V, F);
    std::vector<Vec3> vectors;
    if (params.source == FieldSource::User) {
        if (rosy.is_none())
            throw frontend::UsageError("--field user takes the field from rosy= (n x 3, one vector per vertex of V)");
        vectors = vectorsFromArray(rosy, "rosy");
        if (vectors.size() != input.vertices.size())
            throw InvalidInputError("rosy has " + std::to_string(vectors.size()) + " vectors for " +
                                    std::to_string(input.vertices.size()) + " vertices");
    } else if (!rosy.is_none()) {
        throw frontend::UsageError("rosy= is the field of field='user' only");
    }
    InputField computed;
    TopologySummary topology;
    {
        py::gil_scoped_release release;
        computed = fieldOfInput(input, params, vectors.empty() ? nullptr : &vectors);
        topology = computeTopology(computed.clean);
    }
    FieldOutput out;
    out.vertices = verticesArray(computed.clean.vertices);
    out.faces = facesArray(computed.clean.faces);
    out.normals = verticesArray(computed.field.normals);
    out.rosy = verticesArray(computed.field.directions);
    std::vector<Vec3> positions;
    py::array_t<int> indices(py::ssize_t(computed.singularities.size()));
    for (size_t s = 0; s < computed.singularities.size(); ++s) {
        positions.push_back(computed.singularities[s].position);
        indices.mutable_at(py::ssize_t(s)) = computed.singularities[s].index;
        out.indexSum += computed.singularities[s].index;
    }
    out.singularities = verticesArray(positions);
    out.indices = indices;
    out.eulerCharacteristic = static_cast<long long>(topology.vertices) - topology.edges + topology.faces;
    std::vector<std::string> warnings = computed.report.information;
    warnings.insert(warnings.end(), computed.report.notes.begin(), computed.report.notes.end());
    out.warnings = py::cast(warnings);
    return out;
}

py::object metricsArrays(const py::handle& V, const py::handle& F, const py::object& reference)
{
    const TriMesh mesh = meshFromArrays(V, F);
    TriMesh other;
    if (!reference.is_none()) {
        const py::tuple pair = py::tuple(reference);
        if (pair.size() != 2) throw InvalidInputError("reference must be a pair (V0, F0)");
        other = meshFromArrays(pair[0], pair[1]);
    }
    frontend::MeshMeasurement measured;
    {
        py::gil_scoped_release release;
        measured = frontend::measureMesh(mesh, reference.is_none() ? nullptr : &other);
    }
    return toPython(measured.json());
}

const char* const fieldDoc = R"doc(field(V, F, *, rosy=None, field='extrinsic', seed=1, quiet=False) -> FieldResult

The 6-RoSy direction field of the mesh, as `fcvt field IN OUT.ply` computes it: the input
checked and repaired as remesh does (FieldResult.vertices/faces: that mesh, as the CLI
writes it), per vertex `normals` and `rosy` (n x 3 float64, the field's representative
direction; the six directions are it turned by k * 60 degrees), the singularities
(`singularities`: k x 3 positions, `indices` in sixths of a turn, `index_sum`), the
`euler_characteristic` and the `warnings`. field: extrinsic, curvature-max, curvature-min or
user (then rosy=: n x 3, one vector per vertex).
)doc";

const char* const metricsDoc = R"doc(metrics(V, F, reference=None) -> dict

The figures `fcvt metrics MESH --json [--ref INPUT]` prints: q_min, q_avg, theta_min,
theta_min_avg, theta_max, pct_lt30, pct_gt90, v6_pct, d_rms, d_h, d_boundary,
boundary_v4_pct and, with reference=(V0, F0), the distances to it (fractions of its
bounding-box diagonal; None without it) and parts, part_gap, part_pieces, small_parts,
small_parts_area_pct, small_parts_gap.
)doc";

}  // namespace

void bindFieldAndMetrics(py::module_& m)
{
    py::class_<FieldOutput>(m, "FieldResult", "What fcvt.field returns.")
        .def_readonly("vertices", &FieldOutput::vertices, "n x 3 float64: the checked input's vertices")
        .def_readonly("faces", &FieldOutput::faces, "m x 3 int32: its triangles")
        .def_readonly("normals", &FieldOutput::normals, "n x 3 float64: unit normals")
        .def_readonly("rosy", &FieldOutput::rosy, "n x 3 float64: the field's representative direction per vertex")
        .def_readonly("singularities", &FieldOutput::singularities, "k x 3 float64: the singularities' positions")
        .def_readonly("indices", &FieldOutput::indices, "k int32: their indices in sixths of a turn")
        .def_readonly("index_sum", &FieldOutput::indexSum, "sum of the indices (6 chi on a closed surface)")
        .def_readonly("euler_characteristic", &FieldOutput::eulerCharacteristic, "V - E + F of the checked mesh")
        .def_readonly("warnings", &FieldOutput::warnings, "list of str: what the check and repair did");
    m.def("field", &fieldArrays, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("rosy") = py::none(), fieldDoc);
    m.def("metrics", &metricsArrays, py::arg("V"), py::arg("F"), py::arg("reference") = py::none(), metricsDoc);
}

}  // namespace fieldcvt::python
