#include "arrays.h"

#include "errors.h"

#include <cstring>
#include <limits>

namespace fieldcvt::python {

namespace {

//! A 2-D array of `columns` columns as a C-contiguous array of T (a copy when needed); numbers
//! of another kind (complex, objects, strings; floats for integers) are refused.
template <typename T>
py::array_t<T, py::array::c_style | py::array::forcecast> matrix(const py::handle& object, const std::string& what,
                                                                 py::ssize_t columns, const char* kinds)
{
    const py::array array = py::array::ensure(object);
    if (!array) throw InvalidInputError(what + " must be a NumPy array (or a sequence convertible to one)");
    if (array.ndim() != 2 || array.shape(1) != columns)
        throw InvalidInputError(what + " must have shape (n, " + std::to_string(columns) + "), got " +
                                py::str(array.attr("shape")).cast<std::string>());
    const char kind = array.dtype().kind();
    if (array.size() > 0 && std::strchr(kinds, kind) == nullptr)
        throw InvalidInputError(what + " has dtype " + py::str(array.dtype()).cast<std::string>() + "; expected " +
                                (std::strcmp(kinds, "iub") == 0 ? "integers" : "real numbers"));
    return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(array);
}

}  // namespace

std::vector<Vec3> vectorsFromArray(const py::handle& object, const std::string& what)
{
    const auto a = matrix<double>(object, what, 3, "fiub");
    const auto r = a.unchecked<2>();
    std::vector<Vec3> out(static_cast<size_t>(a.shape(0)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i) out[size_t(i)] = Vec3(r(i, 0), r(i, 1), r(i, 2));
    return out;
}

TriMesh meshFromArrays(const py::handle& vertices, const py::handle& faces)
{
    TriMesh mesh;
    mesh.vertices = vectorsFromArray(vertices, "V");
    const auto f = matrix<long long>(faces, "F", 3, "iub");
    const auto r = f.unchecked<2>();
    mesh.faces.resize(static_cast<size_t>(f.shape(0)));
    for (py::ssize_t i = 0; i < f.shape(0); ++i)
        for (int k = 0; k < 3; ++k) {
            const long long v = r(i, k);
            if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
                throw InvalidInputError("face " + std::to_string(i) + " has the vertex index " + std::to_string(v) +
                                        ", out of range (" + std::to_string(mesh.vertices.size()) + " vertices)");
            mesh.faces[size_t(i)][size_t(k)] = static_cast<int>(v);
        }
    return mesh;
}

std::vector<char> flagsFromArray(const py::handle& object, size_t count, const std::string& what)
{
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!a || a.ndim() != 1 || size_t(a.shape(0)) != count)
        throw InvalidInputError(what + " must be one value per face (" + std::to_string(count) + "), non-zero selected");
    std::vector<char> flags(count);
    for (size_t i = 0; i < count; ++i) flags[i] = a.at(py::ssize_t(i)) != 0 && a.at(py::ssize_t(i)) == a.at(py::ssize_t(i));
    return flags;
}

py::array_t<double> verticesArray(const std::vector<Vec3>& vertices)
{
    py::array_t<double> out({py::ssize_t(vertices.size()), py::ssize_t(3)});
    auto w = out.mutable_unchecked<2>();
    for (size_t i = 0; i < vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) w(py::ssize_t(i), k) = vertices[i][k];
    return out;
}

py::array_t<int> facesArray(const std::vector<Face>& faces)
{
    py::array_t<int> out({py::ssize_t(faces.size()), py::ssize_t(3)});
    auto w = out.mutable_unchecked<2>();
    for (size_t i = 0; i < faces.size(); ++i)
        for (int k = 0; k < 3; ++k) w(py::ssize_t(i), k) = faces[i][size_t(k)];
    return out;
}

}  // namespace fieldcvt::python
