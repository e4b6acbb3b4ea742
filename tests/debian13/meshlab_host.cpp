// fcvt-meshlab-host: runs .mlx filter scripts through MeshLab 2022.02's own plugin manager, for
// the tests of the Debian 13 package (MeshLab 2022.02 has no meshlabserver). Linked against
// Debian 13's libmeshlab-common; built inside the Debian 13 root (scripts/package-debian.sh).
//
// It takes the subset of meshlabserver 2020.09's command line the tests in tests/meshlab/ use and
// prints the same lines they check, so those tests run unchanged against MeshLab 2022.02:
//
//   fcvt-meshlab-host -P PLUGIN_DIR [-d DUMP] [-y NAMES] [-i MESH...] [-o OUT [-l x|c|N] [-m vc vq ...]]...
//                     [-s SCRIPT.mlx]
//
//   -P   the plugin directory PluginManager::loadPlugins() loads (every *.so in it)
//   -d   writes the filters of libfilter_fcvt.so and their parameters in meshlabserver's -d
//        format (only ours: most MeshLab 2022.02 filters cannot declare parameters without a mesh)
//   -y   writes, per filter of libfilter_fcvt.so, the names pymeshlab gives it and its
//        parameters (pythonFilterName, RichParameter::pythonName): "filter: param param ..."
//   -i   opens meshes with meshlab::loadMeshWithStandardParameters (the IO plugins)
//   -s   applies the script: per filter, the filter's own parameter list (initParameterList)
//        with the script's values set over it (a script may omit parameters, not add unknown
//        ones), then FilterPlugin::applyFilter; the log after each filter on stdout; a failure
//        (MLException) prints "Problem with filter: NAME" and exits with status 255
//   -o   saves a layer (the current one, -l x the last, -l N the N-th) with the IO plugin of
//        its extension; -m picks the per-vertex/face data to write, as in meshlabserver
#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <common/GLLogStream.h>
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>
#include <wrap/io_trimesh/io_mask.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {

struct Output {
    QString file;
    int layer = -1;  // -1: current, -2: last, else the index
    int mask = 0;
};

[[noreturn]] void die(const QString& message)
{
    std::fprintf(stdout, "%s\n", qUtf8Printable(message));
    std::fflush(stdout);
    std::exit(255);  // meshlabserver's exit(-1)
}

int maskBit(const std::string& flag)
{
    using M = vcg::tri::io::Mask;
    static const std::map<std::string, int> bits = {
        {"vc", M::IOM_VERTCOLOR},    {"vf", M::IOM_VERTFLAGS},    {"vq", M::IOM_VERTQUALITY}, {"vn", M::IOM_VERTNORMAL},
        {"vt", M::IOM_VERTTEXCOORD}, {"vr", M::IOM_VERTRADIUS},   {"fc", M::IOM_FACECOLOR},   {"ff", M::IOM_FACEFLAGS},
        {"fq", M::IOM_FACEQUALITY},  {"fn", M::IOM_FACENORMAL},   {"wc", M::IOM_WEDGCOLOR},   {"wn", M::IOM_WEDGNORMAL},
        {"wt", M::IOM_WEDGTEXCOORD}, {"mp", M::IOM_BITPOLYGONAL},
    };
    const auto it = bits.find(flag);
    if (it == bits.end()) die(QString("unknown -m flag %1").arg(QString::fromStdString(flag)));
    return it->second;
}

bool isOption(const char* a) { return a[0] == '-' && a[1] != '\0'; }

void printLog(const GLLogStream& log)
{
    QStringList lines;
    log.print(lines);
    for (const QString& line : lines) std::fprintf(stdout, "%s\n", qUtf8Printable(line));
    std::fflush(stdout);
}

// Calls visit(plugin, action) for each filter of libfilter_fcvt.so (the only ones the dumps list).
template <class Visit>
void forEachFcvtFilter(PluginManager& pm, Visit visit)
{
    for (FilterPlugin* plugin : pm.filterPluginIterator())
        if (plugin->pluginFileInfo().fileName() == "libfilter_fcvt.so")
            for (QAction* action : plugin->actions()) visit(*plugin, action);
}

void dumpFilters(PluginManager& pm, const QString& path)
{
    FILE* fp = std::fopen(qUtf8Printable(path), "w");
    if (fp == nullptr) die("cannot write " + path);
    MeshDocument md;  // no mesh, as meshlabserver -d
    int i = 0;
    std::fprintf(fp, "/*! \\mainpage MeshLab Filter Documentation\n");
    forEachFcvtFilter(pm, [&](FilterPlugin& plugin, QAction* action) {
        std::fprintf(fp, "\n\\section f%i %s \n\n%s\n", i++, qUtf8Printable(action->text()),
                     qUtf8Printable(plugin.filterInfo(action)));
        std::fprintf(fp, "<H2> Parameters </h2>\n");
        const RichParameterList params = plugin.initParameterList(action, md);
        std::fprintf(fp, "<TABLE>\n");
        for (const RichParameter& p : params)
            std::fprintf(fp, "<TR><TD> \\c %s  </TD> <TD> %s </TD> <TD><i> %s -- </i></TD> </TR>\n",
                         qUtf8Printable(p.stringType().mid(4)), qUtf8Printable(p.fieldDescription()),
                         qUtf8Printable(p.toolTip()));
        std::fprintf(fp, "</TABLE>\n");
    });
    std::fprintf(fp, "*/");
    std::fclose(fp);
}

// The names a pymeshlab built on this MeshLab calls our filters and parameters by.
void dumpPythonNames(PluginManager& pm, const QString& path)
{
    FILE* fp = std::fopen(qUtf8Printable(path), "w");
    if (fp == nullptr) die("cannot write " + path);
    MeshDocument md;
    forEachFcvtFilter(pm, [&](FilterPlugin& plugin, QAction* action) {
        std::fprintf(fp, "%s:", qUtf8Printable(plugin.pythonFilterName(action)));
        for (const RichParameter& p : plugin.initParameterList(action, md))
            std::fprintf(fp, " %s", qUtf8Printable(p.pythonName()));
        std::fprintf(fp, "\n");
    });
    std::fclose(fp);
}

bool progress(const int, const char*) { return true; }

void runScript(PluginManager& pm, MeshDocument& md, const QString& script)
{
    FilterScript filters;
    if (!filters.open(script)) die("File " + script + " was not found or is not a filter script.");
    std::fprintf(stdout, "Starting Script of %i actions", int(filters.size()));
    GLLogStream log;
    for (FilterNameParameterValuesPair& pair : filters) {
        const QString name = pair.filterName();
        std::fprintf(stdout, "filter: %s\n", qUtf8Printable(name));
        QAction* action = pm.filterAction(name);
        if (action == nullptr) die("filter " + name + " not found");
        FilterPlugin* filter = pm.getFilterPluginFromAction(action);
        filter->setLog(&log);
        if (md.mm() != nullptr) md.mm()->updateDataMask(filter->getRequirements(action));
        // The filter's own list (its defaults) with the script's values set over it.
        RichParameterList params = filter->initParameterList(action, md);
        for (const RichParameter& given : pair.second) {
            if (!params.hasParameter(given.name()))
                die(QString("The parameter %1 in the script is not a parameter of the filter %2.").arg(given.name(), name));
            params.setValue(given.name(), given.value());
        }
        unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
        try {
            md.setBusy(true);
            filter->applyFilter(action, params, md, postConditionMask, progress);
            md.setBusy(false);
        } catch (const MLException& e) {
            printLog(log);
            std::fprintf(stdout, "Filter failed: %s\n", e.what());
            die("Problem with filter: " + name);
        }
        printLog(log);
    }
}

void save(PluginManager& pm, MeshDocument& md, const Output& out)
{
    MeshModel* m = nullptr;
    if (out.layer == -1) {
        m = md.mm();
    } else {
        int index = 0;
        const int wanted = out.layer == -2 ? int(md.meshNumber()) - 1 : out.layer;
        for (auto it = md.meshBegin(); it != md.meshEnd(); ++it, ++index)
            if (index == wanted) m = &*it;
    }
    if (m == nullptr) die("Output mesh " + out.file + " has NOT been saved. A not existent layer has been requested to be saved");
    const QString ext = QFileInfo(out.file).suffix().toLower();
    IOPlugin* io = pm.outputMeshPlugin(ext);
    if (io == nullptr) die("no plugin saves ." + ext);
    int capability = 0, defaultBits = 0;
    io->exportMaskCapability(ext, capability, defaultBits);
    const RichParameterList params = io->initSaveParameter(ext, *m);
    try {
        io->save(ext, out.file, *m, out.mask & capability, params, nullptr);
        // The images too, as MeshLab's File > Export Mesh does: a baked texture lives only in the layer.
        if (out.mask & capability & vcg::tri::io::Mask::IOM_WEDGTEXCOORD) m->saveTextures(QFileInfo(out.file).absolutePath());
    } catch (const MLException& e) {
        die(QString("Output mesh %1 has NOT been saved: %2").arg(out.file, e.what()));
    }
    std::fprintf(stdout, "Mesh %s saved as %s (%i vn %i fn)\n", qUtf8Printable(m->fullName()), qUtf8Printable(out.file), m->cm.vn,
                 m->cm.fn);
}

}  // namespace

int main(int argc, char* argv[])
{
    // No display needed: every filter here runs without OpenGL.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    QString pluginDir, dump, pythonNames, script;
    QStringList inputs;
    std::vector<Output> outputs;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc && !isOption(argv[i + 1]);
        if (a == "-P" && hasValue) {
            pluginDir = QString::fromLocal8Bit(argv[++i]);
        } else if (a == "-d" && hasValue) {
            dump = QFileInfo(QString::fromLocal8Bit(argv[++i])).absoluteFilePath();
        } else if (a == "-y" && hasValue) {
            pythonNames = QFileInfo(QString::fromLocal8Bit(argv[++i])).absoluteFilePath();
        } else if (a == "-s" && hasValue) {
            script = QFileInfo(QString::fromLocal8Bit(argv[++i])).absoluteFilePath();
        } else if (a == "-i") {
            while (i + 1 < argc && !isOption(argv[i + 1]))
                inputs << QFileInfo(QString::fromLocal8Bit(argv[++i])).absoluteFilePath();
        } else if (a == "-o" && hasValue) {
            Output out;
            out.file = QFileInfo(QString::fromLocal8Bit(argv[++i])).absoluteFilePath();
            std::fprintf(stdout, "output mesh  %s\n", qUtf8Printable(out.file));
            if (i + 2 < argc && std::string(argv[i + 1]) == "-l") {
                const std::string l = argv[i + 2];
                out.layer = l == "x" ? -2 : l == "c" ? -1 : std::atoi(l.c_str());
                i += 2;
            }
            if (i + 1 < argc && std::string(argv[i + 1]) == "-m") {
                ++i;
                while (i + 1 < argc && !isOption(argv[i + 1])) out.mask |= maskBit(argv[++i]);
            }
            outputs.push_back(out);
        } else {
            die(QString("usage: fcvt-meshlab-host -P PLUGIN_DIR [-d DUMP] [-y NAMES] [-i MESH...] "
                        "[-o OUT [-l x|c|N] [-m FLAGS...]]... [-s SCRIPT] (at '%1')")
                    .arg(QString::fromStdString(a)));
        }
    }
    if (pluginDir.isEmpty()) die("-P PLUGIN_DIR is required");

    PluginManager& pm = meshlab::pluginManagerInstance();
    const QDir dir(pluginDir);
    std::fprintf(stderr, "Current Plugins Dir is: %s \n", qUtf8Printable(dir.absolutePath()));
    try {
        pm.loadPlugins(dir);
    } catch (const MLException& e) {
        // Every other plugin is still loaded; ours must be among them (checked by its use).
        std::fprintf(stderr, "plugin manager: %s\n", e.what());
    }
    std::fprintf(stderr, "%u plugins loaded\n", pm.size());

    if (!dump.isEmpty()) dumpFilters(pm, dump);
    if (!pythonNames.isEmpty()) dumpPythonNames(pm, pythonNames);

    MeshDocument md;
    for (const QString& in : inputs) {
        try {
            const std::list<MeshModel*> loaded = meshlab::loadMeshWithStandardParameters(in, md);
            for (MeshModel* m : loaded)
                std::fprintf(stdout, "Mesh %s loaded has %i vn %i fn\n", qUtf8Printable(in), m->cm.vn, m->cm.fn);
        } catch (const MLException& e) {
            die(QString("It was not possible to import mesh %1: %2").arg(in, e.what()));
        }
    }
    if (!script.isEmpty()) runScript(pm, md, script);
    for (const Output& out : outputs) save(pm, md, out);
    std::fflush(stdout);
    return 0;
}
