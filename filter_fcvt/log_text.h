#pragma once
// The plugin's MeshLab-neutral text: log lines, the dialog's parameter labels and the names the
// error messages use for them. No MeshLab type here (Qt strings and core types only), so the
// same text serves every MeshLab API the plugin is built for.
//
// MeshLab's GUI shows the log as HTML (QPlainTextEdit::appendHtml): anything between a '<' and
// the next '>' is taken for a tag and disappears. The text written here says "under" / "over"
// instead, and plainLogText() is the guard for text from elsewhere (layer names, core errors).
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

#include "field.h"
#include "mesh_check.h"
#include "metrics.h"
#include "valence_colour.h"

namespace fcvt_plugin {

//! `text` with every '<' replaced by U+2039 (single left-pointing angle quotation mark), so that
//! MeshLab's HTML log shows all of it; '>' alone is shown as it is and left alone.
QString plainLogText(const QString& text);

//! A figure for the log; NaN (not computed) as "n/a".
QString num(double v, int precision = 4);

//! The dialog label of the parameter `key` (e.g. "vertexCount" -> "Target vertices"); the key
//! itself for an unknown one.
QString parameterLabel(const char* key);

//! How error messages name a parameter: its dialog label, then the .mlx key for scripts, e.g.
//! "'Target vertices' (vertexCount)".
QString parameterName(const char* key);

//! "12 singularities, index sum 12 (in sixths of a turn: ...)". `topology` is the surface the
//! field lives on: a closed one's sum is 6 x its Euler characteristic (Poincare-Hopf); with
//! boundary loops the log says that the sum need not be.
QString singularitySummary(const std::vector<fieldcvt::Singularity>& singularities, const fieldcvt::TopologySummary& topology);

//! The core's stage names as the status bar shows them ("cvt 12/65" -> "FCVT: CVT iterations 12/65").
QString stageLabel(const std::string& stage);

//! The Table 2 figures of computeQuality as one log line (distances apart).
QString qualityText(const fieldcvt::QualityMetrics& m);

//! "genus 1, 0 boundary loops, 1 components".
QString topologyText(const fieldcvt::TopologySummary& t);

//! What "Compute 6-RoSy Field" left out or read differently on a copy of the layer (the layer
//! itself is not changed), one phrase per repair of the input check, e.g. "1113 vertices on no
//! face (their rosy is (0,0,0))"; empty when the check changed nothing. The note on several
//! connected components is not in it (nothing is ignored there).
QStringList fieldIgnoredText(const fieldcvt::InputReport& report);

//! The counts of each valence colour as one log line.
QString valenceColourText(const ValenceColouring& c);

}  // namespace fcvt_plugin
