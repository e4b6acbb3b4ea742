#pragma once
// The MeshLab-neutral part of the plugin: the three filters' names, descriptions, parameters
// (names, types, defaults, labels: the .mlx API, the same in every MeshLab), their checks, the
// conversion between MeshLab layers and fieldcvt::TriMesh, the calls into the core and the log
// text. It uses only what MeshLab 2020.09 and 2022.02 share (CMeshO, MeshModel, MeshDocument,
// QString); the plugin API of each MeshLab (MeshFilterInterface or FilterPlugin, their parameter
// lists, logging and error reporting) is the thin glue in meshlab2020/ and meshlab2022/.
#include <QString>

#include <exception>
#include <vector>

#include "filter_types.h"
#include "meshlab_types.h"

namespace fcvt_plugin {

QString pluginName();
QString filterName(FilterId filter);  //!< frozen: the key of .mlx scripts
QString filterInfo(FilterId filter);
FilterKind filterKind(FilterId filter);
int preConditions(FilterId filter);  //!< MeshModel::MM_* mask
int postCondition(FilterId filter);  //!< MeshModel::MM_* mask

//! The parameters of `filter`, in their declaration (= .mlx) order. `current` (may be null: no
//! mesh loaded) gives the defaults that depend on the mesh; a Mesh parameter defaults to it.
std::vector<ParamDef> parameters(FilterId filter, const MeshModel* current);

//! The value a user typed for a float parameter. MeshLab keeps it in single precision (0.002
//! becomes 0.0020000000949949...) where the CLI parses the text into a double; the shortest
//! decimal that reads back as the same float is the text typed, so the filter and the CLI run
//! with the same double. (Measured: lambda 0.002 as a float moved the optimised samples by about
//! 1e-9 of their coordinates, and the thin-part passes then kept another pass: casting.off at
//! 637 vertices came back with 1 073 vertices from the filter, 1 218 from the CLI.)
double typedValue(float value);

//! Runs `filter` on the document and returns its figures (FilterOutput; with `figures` false
//! only those that cost nothing extra). Throws FilterFailure (bad parameters or input) or any
//! other exception (a failure in the core); in both cases the document is as it was before.
FilterOutput applyFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log, Callback* cb,
                         bool figures = true);

//! The message for an unexpected exception (anything but FilterFailure).
QString unexpectedFailure(const std::exception* e);

//! applyFilter for the glue, which must let nothing escape into MeshLab (MeshLab 2020.09's GUI
//! catches only std::bad_alloc and meshlabserver nothing at all; 2022.02 ends on anything but
//! its MLException): true when the filter ran. Otherwise false, and `failure` holds the message
//! as a log line (plainLogText), already logged as a warning; the glue reports it its MeshLab's
//! way (2020.09: errorMessage, since meshlabserver prints the log but never errorMsg();
//! 2022.02: an MLException). When it ran and `output` is given, `*output` holds its figures (the
//! FilterPlugin glue returns them to MeshLab and pymeshlab; the 2020.09 glue passes none).
bool runFilter(FilterId filter, MeshDocument& md, const ParamValues& par, FilterLog& log, Callback* cb, QString& failure,
               FilterOutput* output = nullptr);

}  // namespace fcvt_plugin
