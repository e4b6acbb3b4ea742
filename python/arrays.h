#pragma once
// NumPy arrays <-> the core's types for the Python module: shapes and types checked here (a
// ValueError through fieldcvt::InvalidInputError), the mesh's own faults (NaN, bad indices,
// non-manifold edges) left to the core's checks, which say them as the CLI does.
#include "mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace fieldcvt::python {

namespace py = pybind11;

//! `vertices` (n x 3, any real type) and `faces` (m x 3, any integer type) as a TriMesh;
//! InvalidInputError naming `what` ("V", "F") for another shape or type, or an index beyond int.
TriMesh meshFromArrays(const py::handle& vertices, const py::handle& faces);

//! An n x 3 array of finite or non-finite doubles (`what` names it in the errors), as vectors.
std::vector<Vec3> vectorsFromArray(const py::handle& array, const std::string& what);

//! One value per face, non-zero selected (`count` of them), as flags.
std::vector<char> flagsFromArray(const py::handle& array, size_t count, const std::string& what);

//! n x 3 float64 and m x 3 int32 copies.
py::array_t<double> verticesArray(const std::vector<Vec3>& vertices);
py::array_t<int> facesArray(const std::vector<Face>& faces);

}  // namespace fieldcvt::python
