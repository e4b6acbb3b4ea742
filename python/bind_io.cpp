// fcvt.read(path) and fcvt.write(path, V, F, ...): the project's readers and writers (io/), the
// formats of the CLI by extension (PLY, OBJ, OFF, STL).
#include "arrays.h"
#include "bindings.h"

#include "errors.h"
#include "mesh_io.h"

#include <string>

namespace fieldcvt::python {

namespace {

py::tuple readArrays(const std::string& path)
{
    TriMesh mesh;
    {
        py::gil_scoped_release release;
        mesh = readMesh(path);
    }
    return py::make_tuple(verticesArray(mesh.vertices), facesArray(mesh.faces));
}

std::vector<Vec3> perVertex(const py::object& array, const std::string& what, size_t count)
{
    if (array.is_none()) return {};
    std::vector<Vec3> vectors = vectorsFromArray(array, what);
    if (vectors.size() != count)
        throw InvalidInputError(what + " has " + std::to_string(vectors.size()) + " rows for " + std::to_string(count) +
                                " vertices");
    return vectors;
}

void writeArrays(const std::string& path, const py::handle& V, const py::handle& F, const py::object& normals,
                 const py::object& rosy)
{
    const TriMesh mesh = meshFromArrays(V, F);
    VertexAttributes attributes;
    attributes.normals = perVertex(normals, "normals", mesh.vertices.size());
    attributes.rosy = perVertex(rosy, "rosy", mesh.vertices.size());
    const bool withAttributes = !attributes.normals.empty() || !attributes.rosy.empty();
    py::gil_scoped_release release;
    writeMesh(path, mesh, withAttributes ? &attributes : nullptr);
}

}  // namespace

void bindIo(py::module_& m)
{
    m.def("read", &readArrays, py::arg("path"),
          "read(path) -> (V, F)\n\nThe mesh file (PLY, OBJ, OFF, STL by extension; polygons triangulated) as V (n x 3 "
          "float64) and F (m x 3 int32), with the reader of `fcvt`. Raises OSError when the file cannot be read.");
    m.def("write", &writeArrays, py::arg("path"), py::arg("V"), py::arg("F"), py::kw_only(), py::arg("normals") = py::none(),
          py::arg("rosy") = py::none(),
          "write(path, V, F, *, normals=None, rosy=None)\n\nWrites the mesh by extension (PLY binary with double "
          "coordinates, OBJ, OFF, STL) with the writer of `fcvt`. A PLY gets normals (nx ny nz) and rosy (rosy_x rosy_y "
          "rosy_z) per vertex when given, as `fcvt remesh` writes its field (Result.normals, Result.rosy). Raises "
          "OSError when the file cannot be written.");
}

}  // namespace fieldcvt::python
