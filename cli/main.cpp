// `fcvt`: field-aligned CVT remeshing from the command line. Every failure ends as exactly one
// line "fcvt: error: <message>" on stderr: exit code 2 for usage errors, 1 for the rest.
#include "cli_common.h"
#include "commands.h"
#include "errors.h"
#include "huge_pages.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace {

const char* const usage =
    "Usage: fcvt <command> [options]\n"
    "\n"
    "Field-aligned CVT isotropic remeshing of triangle meshes (PLY, OBJ, OFF, STL).\n"
    "\n"
    "Commands:\n"
    "  remesh IN OUT --vertices N [options]   remesh IN into OUT with about N vertices\n"
    "  field IN OUT.ply [options]             the 6-RoSy direction field of IN and its singularities\n"
    "  compare IN --vertices N [options]      CVT vs FCVT on IN, one row per method (paper's Table 2)\n"
    "  metrics MESH [--ref INPUT] [--json]    quality metrics and topology of a mesh\n"
    "  convert IN OUT                         IN in OUT's format (by extension), after remesh's input checks\n"
    "  texture-compare IN OUT [options]       how OUT's texture differs from IN's, rendered from the same cameras\n"
    "\n"
    "Options:\n"
    "  -h, --help     show this help; 'fcvt <command> --help' shows a command's options\n"
    "  --version      print the version\n"
    "\n"
    "Exit status: 0 success, 1 runtime error, 2 usage error.\n";

//! One line, whatever the exception text holds.
void printError(std::string message)
{
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "fcvt: error: %s\n", fieldcvt::escapeControlCharacters(message).c_str());
}

int run(const std::vector<std::string>& args)
{
    using namespace fieldcvt::cli;
    if (args.empty()) throw UsageError("no command given (try 'fcvt --help')");
    const std::string& command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(usage, stdout);
        return 0;
    }
    if (command == "--version") {
        std::printf("fcvt %s\n", FCVT_VERSION);
        return 0;
    }
    if (command == "remesh") return runRemesh(rest);
    if (command == "metrics") return runMetrics(rest);
    if (command == "field") return runField(rest);
    if (command == "compare") return runCompare(rest);
    if (command == "convert") return runConvert(rest);
    if (command == "texture-compare") return runTextureCompare(rest);
    throw UsageError("unknown command '" + command + "' (try 'fcvt --help')");
}

}  // namespace

int main(int argc, char** argv)
{
    // The whole command's memory in huge pages, the input's too (remesh() alone would cover only
    // what its stages allocate): in-process, as the MeshLab filter gets them (huge_pages.h).
    const fieldcvt::HugePageHeap heap;
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const fieldcvt::cli::UsageError& e) {
        printError(e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        printError("out of memory");
        return 1;
    } catch (const std::exception& e) {
        printError(e.what());
        return 1;
    } catch (...) {
        printError("unexpected internal error");
        return 1;
    }
}
