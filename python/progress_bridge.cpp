#include "progress_bridge.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fieldcvt::python {

ProgressBridge::ProgressBridge(py::object callback) : callback_(std::move(callback))
{
    if (callback_.is_none())
        callback_ = py::object();
    else if (!PyCallable_Check(callback_.ptr()))
        throw py::type_error("progress must be a callable (stage: str, percent: int), got " +
                             py::repr(callback_).cast<std::string>());
}

Progress ProgressBridge::callback()
{
    return [this](const std::string& stage, double percent) { return report(stage, percent); };
}

bool ProgressBridge::report(const std::string& stage, double percent)
{
    // The core reports from the calling thread; a lock in case a stage reports from its workers.
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return false;
    const int whole = std::max(percent_, std::isfinite(percent) ? std::clamp(static_cast<int>(percent), 0, 100) : 0);
    py::gil_scoped_acquire gil;
    try {
        // Python runs its signal handlers in the main thread only (elsewhere this returns 0).
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (callback_ && (whole != percent_ || stage != stage_)) {
            percent_ = whole;
            stage_ = stage;
            callback_(stage, whole);
        }
    } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
        return false;  // the core throws CancelledError
    }
    return true;
}

void ProgressBridge::rethrowIfFailed()
{
    if (!error_) return;
    py::error_already_set e = std::move(*error_);
    error_.reset();
    throw e;
}

}  // namespace fieldcvt::python
