#pragma once
/// @file
/// Plots of a study's results.csv: analysis/plot_study.py (compiled into the library, so the
/// binary does not read the source tree) run with Debian's python3 and matplotlib.

#include <string>
#include <vector>

namespace graspsim::study {

/// What plotting did: the PNG files written, or why there are none.
struct PlotOutcome {
    std::vector<std::string> files;  ///< relative to the study folder, e.g. "plots/held.png"
    std::string skipped;             ///< empty, or one line saying why no plots were drawn
};

/// Writes the script to `folder`/plot_study.py (to redraw by hand) and runs it on `folder`.
/// When the interpreter ($GRASPSIM_PYTHON, else /usr/bin/python3) is missing or the script
/// fails, returns the reason instead of throwing: the results table stands without plots.
PlotOutcome drawStudyPlots(const std::string& folder);

}  // namespace graspsim::study
