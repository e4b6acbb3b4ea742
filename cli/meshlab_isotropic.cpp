#include "meshlab_isotropic.h"

#include "errors.h"
#include "mesh_io.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fieldcvt::cli {

namespace {

bool executable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }

//! `name` on PATH, or empty.
std::string onPath(const std::string& name)
{
    const char* path = std::getenv("PATH");
    if (path == nullptr) return {};
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
        struct stat st;
        if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && executable(candidate)) return candidate;
    }
    return {};
}

//! A private temporary directory, removed with its files when this goes out of scope.
class TempDir {
public:
    TempDir()
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/fcvt-meshlab-XXXXXX";
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        if (::mkdtemp(buffer.data()) == nullptr)
            throw IOError("cannot create a temporary directory in " + pattern + ": " + std::strerror(errno));
        path_ = buffer.data();
    }
    ~TempDir()
    {
        for (const std::string& f : files_) std::remove((path_ + "/" + f).c_str());
        ::rmdir(path_.c_str());
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    //! The path of file `name` in the directory (removed with it).
    std::string file(const std::string& name)
    {
        files_.push_back(name);
        return path_ + "/" + name;
    }

private:
    std::string path_;
    std::vector<std::string> files_;
};

//! Runs argv with stdout and stderr to `logPath`; kills its process group after `timeoutSeconds`.
//! Returns the exit status (128 + N for signal N, -1 if it could not start).
int runProcess(const std::vector<std::string>& argv, const std::string& logPath, double timeoutSeconds)
{
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        ::setpgid(0, 0);
        const int fd = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) {
            ::dup2(fd, STDOUT_FILENO);
            ::dup2(fd, STDERR_FILENO);
            ::close(fd);
        }
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, STDIN_FILENO);
        ::execvp(args[0], args.data());
        std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
        ::_exit(127);
    }
    ::setpgid(pid, pid);
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) return -1;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > timeoutSeconds) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            return 128 + SIGKILL;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return -1;
}

//! The last `lines` lines of a file, joined by " | ".
std::string tail(const std::string& path, size_t lines)
{
    std::ifstream in(path);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) all.push_back(line);
    std::string out;
    for (size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += (out.empty() ? "" : " | ") + all[i];
    return out;
}

//! The filter script: every parameter listed (meshlabserver 2020.09 asserts on a missing one).
std::string isotropicScript(double targetLength, double diagonal, int iterations)
{
    char len[64], diag[64], surf[64];
    std::snprintf(len, sizeof len, "%.9g", targetLength);
    std::snprintf(diag, sizeof diag, "%.9g", diagonal);
    std::snprintf(surf, sizeof surf, "%.9g", 0.01 * diagonal);
    std::ostringstream s;
    s << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
      << " <filter name=\"Remeshing: Isotropic Explicit Remeshing\">\n"
      << "  <Param type=\"RichInt\" name=\"Iterations\" value=\"" << iterations << "\"/>\n"
      << "  <Param type=\"RichBool\" name=\"Adaptive\" value=\"false\"/>\n"
      << "  <Param type=\"RichBool\" name=\"SelectedOnly\" value=\"false\"/>\n"
      << "  <Param type=\"RichAbsPerc\" name=\"TargetLen\" value=\"" << len << "\" min=\"0\" max=\"" << diag << "\"/>\n"
      << "  <Param type=\"RichFloat\" name=\"FeatureDeg\" value=\"30\"/>\n"
      << "  <Param type=\"RichBool\" name=\"CheckSurfDist\" value=\"false\"/>\n"
      << "  <Param type=\"RichAbsPerc\" name=\"MaxSurfDist\" value=\"" << surf << "\" min=\"0\" max=\"" << diag << "\"/>\n"
      << "  <Param type=\"RichBool\" name=\"SplitFlag\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"CollapseFlag\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"SwapFlag\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"SmoothFlag\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"ReprojectFlag\" value=\"true\"/>\n"
      << " </filter>\n</FilterScript>\n";
    return s.str();
}

}  // namespace

std::string findMeshlabserver(const std::string& explicitPath)
{
    if (!explicitPath.empty()) return executable(explicitPath) ? explicitPath : std::string();
    if (const char* env = std::getenv("FCVT_MESHLABSERVER"); env != nullptr && *env != '\0')
        return executable(env) ? std::string(env) : std::string();
    return onPath("meshlabserver");
}

IsotropicRun runMeshlabIsotropic(const std::string& server, const TriMesh& input, int vertices, int iterations)
{
    if (input.faces.empty()) throw InvalidInputError("meshlab-isotropic: the input has no faces");
    const double area = surfaceArea(input);
    Vec3 lo = input.vertices[0], hi = input.vertices[0];
    for (const Vec3& p : input.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double diagonal = (hi - lo).norm();

    TempDir dir;
    const std::string inPath = dir.file("in.ply");
    const std::string outPath = dir.file("out.ply");
    const std::string scriptPath = dir.file("isotropic.mlx");
    const std::string logPath = dir.file("log.txt");
    writeMesh(inPath, input);

    std::vector<std::string> command;
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0') {
        const std::string xvfb = onPath("xvfb-run");
        if (xvfb.empty()) throw Error("meshlab-isotropic: no DISPLAY and no xvfb-run (meshlabserver needs an X server)");
        command = {xvfb, "-a"};
    }
    command.insert(command.end(), {server, "-i", inPath, "-o", outPath, "-s", scriptPath});

    IsotropicRun run;
    run.iterations = iterations;
    double length = std::sqrt(2.0 * area / (std::sqrt(3.0) * vertices));
    constexpr int kMaxRuns = 3;
    for (int attempt = 1; attempt <= kMaxRuns; ++attempt) {
        {
            std::ofstream script(scriptPath, std::ios::trunc);
            script << isotropicScript(length, diagonal, iterations);
            if (!script) throw IOError(scriptPath + ": cannot write the filter script");
        }
        std::remove(outPath.c_str());
        const auto start = std::chrono::steady_clock::now();
        const int status = runProcess(command, logPath, 900);
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (status != 0)
            throw Error("meshlab-isotropic: meshlabserver exited with status " + std::to_string(status) + ": " +
                        tail(logPath, 4));
        run.mesh = readMesh(outPath);
        run.targetLength = length;
        run.runs = attempt;
        const int got = run.mesh.vertexCount();
        char note[160];
        std::snprintf(note, sizeof note, "run %d: TargetLen %.6g -> %d vertices", attempt, length, got);
        run.notes.push_back(note);
        if (std::abs(got - vertices) <= 0.05 * vertices || got <= 0) break;
        length *= std::sqrt(double(got) / vertices);
    }
    return run;
}

}  // namespace fieldcvt::cli
