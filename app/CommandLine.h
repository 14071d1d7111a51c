#pragma once

#include <functional>
#include <string>
#include <vector>

namespace drytwin::workflow {
struct PipelineResult;
class Session;
} // namespace drytwin::workflow

namespace drytwin::app {

/// @brief What main() should do after the command line was parsed.
struct ParsedCommandLine {
    bool exitNow = false; ///< --help, --version or a usage error: return exitCode
    int exitCode = 0;
    bool gui = false; ///< no subcommand: open the main window
    std::string guiDataPath;
    std::string screenshotPath;  ///< GUI: save a PNG of the window once the data is shown, then quit
    std::string projectPath;     ///< GUI: open this project at start
    std::string language;        ///< GUI: "en" or "zh_CN" (empty: the saved choice, else the locale)
    std::string modelPath;       ///< GUI: open this model file with the data
    std::string mappingPath;     ///< GUI: read the data's columns with this column mapping
    std::string runActions;      ///< GUI: comma-separated actions to run after loading
    std::string referencePath;   ///< GUI: the reference period Discover compares with
    std::string trainingSession; ///< GUI: a saved training session to reopen
    std::string saveProjectPath; ///< GUI: save the project here once the window's work is done
};

/// @brief The `drytwin` command line (CONTRACT.md §2), built on CLI11.
class CommandLine {
public:
    CommandLine();
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    ParsedCommandLine parse(int argc, char** argv);
    /// @brief Runs the parsed subcommand headless; returns the contract's exit code.
    int run();
    /// @brief Hooks for the subcommands that need the GUI's code (the pipeline's HTML/PDF report).
    void setReportRenderer(
        std::function<std::vector<std::string>(const workflow::PipelineResult&, const workflow::Session&,
                                               const std::string&, std::string&)>
            renderer,
        std::string commandLine);

private:
    struct Impl;
    Impl* m_impl;
};

} // namespace drytwin::app
