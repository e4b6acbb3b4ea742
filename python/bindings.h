#pragma once
// The functions of the `fcvt` Python module, one file each group (module.cpp puts them
// together): remesh (bind_remesh.cpp), field and metrics (bind_field_metrics.cpp), read and write
// (bind_io.cpp). Each converts arrays and keywords, runs the core with the GIL released and
// returns NumPy arrays and dicts; the errors map to Python's in module.cpp.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace fieldcvt::python {

namespace py = pybind11;

void bindRemesh(py::module_& m);
void bindFieldAndMetrics(py::module_& m);
void bindIo(py::module_& m);

//! Each of `warnings` as a Python UserWarning (warnings.warn; an error when filtered so).
void issueWarnings(const std::vector<std::string>& warnings);

//! `json` (nlohmann's) as Python's dicts, lists and numbers (through json.loads: the same
//! keys, the same doubles).
template <typename Json>
py::object toPython(const Json& json)
{
    return py::module_::import("json").attr("loads")(json.dump());
}

}  // namespace fieldcvt::python
