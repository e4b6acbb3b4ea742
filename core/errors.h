#pragma once
// Exceptions thrown by the core. The CLI and the MeshLab plugin catch std::exception at their
// boundary and turn it into one clear message.
#include <stdexcept>
#include <string>

namespace fieldcvt {

//! Base of every FCVT error.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};
//! The input mesh or a parameter cannot be processed (message says what and where).
struct InvalidInputError : Error {
    using Error::Error;
};
//! A mesh file cannot be read or written.
struct IOError : Error {
    using Error::Error;
};
//! The optimiser could not make progress at all.
struct SolverError : Error {
    using Error::Error;
};
//! RemeshParams::timeLimitSeconds ran out during an optimisation stage. remesh() catches it
//! and goes on with the best samples so far (and a warning); it never reaches the caller.
struct TimeLimitReached : Error {
    TimeLimitReached() : Error("time limit reached") {}
};
//! The Progress callback asked to stop.
struct CancelledError : Error {
    CancelledError() : Error("cancelled") {}
};

}  // namespace fieldcvt
