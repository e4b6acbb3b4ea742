#pragma once
// The core's Progress for a run with the GIL released: at each report it takes the GIL back,
// runs Python's signal handlers (PyErr_CheckSignals: Ctrl-C) and calls the user's
// `progress(stage, percent)` when the stage or the whole percent changed. A Python exception
// from either (KeyboardInterrupt, or one the callback raised) cancels the run: the core throws
// CancelledError, and rethrowIfFailed() raises the Python exception instead.
#include "progress.h"

#include <pybind11/pybind11.h>

#include <mutex>
#include <optional>
#include <string>

namespace fieldcvt::python {

namespace py = pybind11;

class ProgressBridge {
public:
    //! `callback`: None or a callable (stage: str, percent: int); made with the GIL held.
    explicit ProgressBridge(py::object callback);
    ProgressBridge(const ProgressBridge&) = delete;
    ProgressBridge& operator=(const ProgressBridge&) = delete;

    //! What the core calls (valid while this bridge lives); called without the GIL.
    Progress callback();
    //! With the GIL held, after the run: raises the Python exception that cancelled it, if any.
    void rethrowIfFailed();

private:
    bool report(const std::string& stage, double percent);

    py::object callback_;
    std::mutex mutex_;
    std::optional<py::error_already_set> error_;
    std::string stage_;
    int percent_ = -1;  //!< the last percent passed on (never decreasing)
};

}  // namespace fieldcvt::python
