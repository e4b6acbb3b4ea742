#pragma once
// Progress of a long run on stderr: on a terminal one line rewritten in place (a bar, the percent and
// the stage), plain lines (one per stage change and every 10 %) when stderr is a file or a pipe,
// nothing with --quiet.
#include "progress.h"

#include <mutex>
#include <string>

namespace fieldcvt::cli {

class ProgressPrinter {
public:
    explicit ProgressPrinter(bool quiet);
    ~ProgressPrinter() { finish(); }
    ProgressPrinter(const ProgressPrinter&) = delete;
    ProgressPrinter& operator=(const ProgressPrinter&) = delete;

    //! The callback to hand to the core (valid while this printer lives).
    Progress callback();
    //! Ends the in-place line, so that what is printed next starts on a fresh line.
    void finish();

private:
    void report(const std::string& stage, double percent);

    const bool quiet_;
    const bool terminal_;
    std::mutex mutex_;
    std::string stage_;
    int shown_ = -1;         //!< last percent printed (terminal: tenths, else tens)
    bool lineOpen_ = false;  //!< a terminal line is waiting for its end
};

}  // namespace fieldcvt::cli
