#pragma once
// Exceptions thrown by the core. The CLI and the MeshLab plugin catch std::exception at their
// boundary and turn it into one clear message.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fieldcvt {

//! Base of every FCVT error.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};
//! The input mesh or a parameter cannot be processed (message says what and where).
struct InvalidInputError : Error {
    using Error::Error;
};
//! The input is a valid mesh that is not a manifold, orientable surface: an edge of more than two
//! faces or a non-orientable component, which the strict check (mesh_check.h) refuses and the
//! repair (repair.h) resolves. A front end that writes the mesh as read (fcvt convert) may
//! take it as a warning instead.
struct SurfaceTopologyError : InvalidInputError {
    using InvalidInputError::InvalidInputError;
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

//! Text taken from an input (a token, a header line, an argument) as a message may quote it:
//! in single quotes, at most `maxChars` characters of it (then an ellipsis), control characters
//! and other non-printing bytes shown as \xNN escapes so that a file cannot write terminal
//! escape sequences or a megabyte line through an error message.
std::string quoteInput(std::string_view text, std::size_t maxChars = 80);

//! The message with every control character shown escaped (\xNN), for a front end that prints it
//! on one line: file names and quoted inputs cannot move the cursor or colour the terminal.
std::string escapeControlCharacters(std::string_view message);

}  // namespace fieldcvt
