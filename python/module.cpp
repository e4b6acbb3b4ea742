// `import fcvt`: the FCVT remesher from Python (docs/python.md). The functions live in the
// bind_*.cpp files; here the module, its errors (the CLI's one-line messages as Python
// exceptions) and its warnings.
#include "bindings.h"

#include "arguments.h"
#include "errors.h"

#include <exception>
#include <string>
#include <vector>

namespace fieldcvt::python {

namespace {

//! One line, as the CLI prints it (main.cpp): line breaks as spaces, control characters escaped.
std::string oneLine(std::string message)
{
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    return escapeControlCharacters(message);
}

void translateErrors(std::exception_ptr error)
{
    try {
        if (error) std::rethrow_exception(error);
    } catch (const frontend::UsageError& e) {
        PyErr_SetString(PyExc_ValueError, oneLine(e.what()).c_str());
    } catch (const InvalidInputError& e) {
        PyErr_SetString(PyExc_ValueError, oneLine(e.what()).c_str());
    } catch (const IOError& e) {
        PyErr_SetString(PyExc_OSError, oneLine(e.what()).c_str());
    } catch (const CancelledError& e) {
        PyErr_SetString(PyExc_KeyboardInterrupt, oneLine(e.what()).c_str());
    } catch (const Error& e) {
        PyErr_SetString(PyExc_RuntimeError, oneLine(e.what()).c_str());
    }
}

}  // namespace

void issueWarnings(const std::vector<std::string>& warnings)
{
    for (const std::string& warning : warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, oneLine(warning).c_str(), 1) != 0) throw py::error_already_set();
}

}  // namespace fieldcvt::python

PYBIND11_MODULE(fcvt, m)
{
    using namespace fieldcvt::python;
    m.doc() =
        "FCVT: field-aligned isotropic surface remeshing (the core of the `fcvt` command).\n\n"
        "remesh, field and metrics take NumPy arrays V (n x 3) and F (m x 3) and the options of the matching `fcvt` "
        "command as keywords; read and write use the command's mesh readers and writers. See docs/python.md.";
    m.attr("__version__") = FCVT_VERSION;
    py::register_exception_translator(&translateErrors);
    bindRemesh(m);
    bindFieldAndMetrics(m);
    bindIo(m);
}
