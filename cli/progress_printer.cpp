#include "progress_printer.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace fieldcvt::cli {

ProgressPrinter::ProgressPrinter(bool quiet) : quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1) {}

Progress ProgressPrinter::callback()
{
    if (quiet_) return {};
    return [this](const std::string& stage, double percent) {
        report(stage, percent);
        return true;
    };
}

void ProgressPrinter::report(const std::string& stage, double percent)
{
    std::lock_guard<std::mutex> lock(mutex_);
    percent = percent < 0 ? 0 : percent > 100 ? 100 : percent;
    // Plain lines only start anew with the stage, not with its steps ("cvt 12/65").
    const std::string key = stageName(stage);
    const bool newStage = key != stage_;
    if (terminal_) {
        const int tenths = static_cast<int>(percent * 10);
        if (!newStage && tenths == shown_) return;
        shown_ = tenths;
        // A bar of kBarWidth cells; \33[K clears what a longer previous stage name left on the line.
        constexpr int kBarWidth = 30;
        const int filled = static_cast<int>(percent / 100 * kBarWidth + 0.5);
        const std::string bar =
            std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(kBarWidth - filled), '-');
        std::fprintf(stderr, "\rfcvt: [%s] %5.1f %% %s\33[K", bar.c_str(), percent, stage.c_str());
        lineOpen_ = true;
    } else {
        const int tens = static_cast<int>(percent / 10) * 10;
        if (!newStage && tens <= shown_) return;
        shown_ = tens;
        std::fprintf(stderr, "fcvt: %s %d %%\n", stage.c_str(), static_cast<int>(percent));
    }
    stage_ = key;
    std::fflush(stderr);
}

void ProgressPrinter::finish()
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (lineOpen_) std::fputc('\n', stderr);
    lineOpen_ = false;
}

}  // namespace fieldcvt::cli
