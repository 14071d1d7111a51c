#pragma once

#include <string>
#include <vector>

namespace drytwin::io {

/// @brief One term of the reports' appendix: the plain words the workbench shows a process
/// engineer, and the method behind them by its technical name, which the screen keeps to its
/// tooltips (issue #72 item 10).
struct MethodTerm {
    std::string onScreen; ///< as the workbench says it ("Chance it is noise")
    std::string where;    ///< the tab ("Discover")
    std::string method;   ///< the statistician's or the optimiser's name and what it computes
};

/// @brief Every term, in the order of the workbench's tabs. Thread-safe.
const std::vector<MethodTerm>& methodsGlossary();

/// @brief The appendix as Markdown (a heading and a table), for report.md.
std::string methodsAppendixMarkdown();

} // namespace drytwin::io
