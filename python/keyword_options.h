#pragma once
// Python keywords as a command's options, so that the module takes exactly the CLI's names,
// values, defaults and checks (frontend/): `feature_angle=45` is `--feature-angle 45`,
// `lambda_=0` is `--lambda 0` (a trailing underscore dropped: `lambda` is a Python keyword), a
// flag is a bool (`no_valence=True` is `--no-valence`, False leaves it out), None leaves an
// option out. The values go through Arguments as the command line's text does.
#include "arguments.h"
#include "remesh_options.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace fieldcvt::python {

namespace py = pybind11;

//! The keywords as arguments of a command taking `names` ("help" is not a keyword). An unknown
//! keyword is the CLI's "unknown option '--name'"; a flag that is not a bool a UsageError too.
frontend::Arguments argumentsFromKeywords(const py::kwargs& keywords, const frontend::OptionNames& names);

}  // namespace fieldcvt::python
